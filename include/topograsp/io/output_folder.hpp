// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The output folder of a grasp-transfer run: checked before any work, written through a staging
/// folder inside it, and committed so that a results.json always describes the files beside it.
///
/// The rule (docs/transfer.md): a run owns DIR/results.json, DIR/scenes/, DIR/figures/ and
/// DIR/index.html and nothing else in DIR. Everything is written into
/// DIR/.grasp_transfer-staging-<token>/ first; commit() then removes the old results.json,
/// replaces scenes/, figures/ and index.html entirely (removing an earlier run's even where this
/// run wrote none), and renames results.json into place last. A run that fails or is interrupted
/// before the commit leaves the previous run untouched; its staging folder is removed by the next
/// run into DIR.
#pragma once

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/io/detail/svg_text.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// The "generator" of a results.json written by grasp_transfer (results_json): the mark by which
/// OutputFolder recognises a folder that holds an earlier run.
inline constexpr std::string_view results_generator = "topograsp grasp_transfer";

/// The name prefix of the staging folders inside an output folder.
inline constexpr std::string_view output_staging_prefix = ".grasp_transfer-staging-";

/// Whether the file \p path is a results.json written by grasp_transfer: a JSON object whose
/// "generator" is results_generator, or, from versions before that mark, a JSON object without a
/// "generator" that has the "config" object and the "objects" and "grasps" arrays of the schema.
/// False for anything else, including unreadable files and invalid JSON; never throws but
/// std::bad_alloc.
[[nodiscard]] inline bool is_grasp_transfer_results(const std::filesystem::path& path) {
  try {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const Json doc = Json::parse(text);
    if (!doc.is_object()) return false;
    if (doc.contains("generator"))
      return doc.at("generator").is_string() &&
             doc.at("generator").as_string() == results_generator;
    return doc.contains("config") && doc.at("config").is_object() && doc.contains("objects") &&
           doc.at("objects").is_array() && doc.contains("grasps") && doc.at("grasps").is_array();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (...) {
    return false;
  }
}

/// An output folder being written: the constructor checks the folder and makes the staging
/// folder, staging() is where every file of the run is written, commit() puts them in place, and
/// the destructor removes the staging folder of a run that was not committed.
class OutputFolder {
 public:
  /// The entries of DIR a run owns, and whether each is a folder.
  static constexpr std::array<std::pair<std::string_view, bool>, 4> owned{{
      {"results.json", false},
      {"scenes", true},
      {"figures", true},
      {"index.html", false},
  }};

  /// Checks \p dir before any work and creates DIR/.grasp_transfer-staging-<token>/ in it:
  /// DIR is created if missing; leftover staging folders of interrupted runs are removed.
  /// \throws topograsp::invalid_argument naming \p argument ("dir" by default; grasp_transfer
  /// passes "--out") if \p dir is empty, exists but is not a folder, cannot be created or written,
  /// if DIR/results.json or DIR/index.html exists and is not a regular file, DIR/scenes or
  /// DIR/figures exists and is not a folder, or if DIR holds anything but leftover staging folders
  /// and has no results.json written by grasp_transfer (is_grasp_transfer_results), unless
  /// \p force. Nothing in DIR is changed then, except that DIR may have been created.
  explicit OutputFolder(std::filesystem::path dir, bool force = false,
                        std::string_view argument = "dir")
      : dir_(std::move(dir)) {
    namespace fs = std::filesystem;
    const auto refuse = [&](const std::string& what) {
      detail::throw_invalid_argument(argument, what);
    };
    if (dir_.empty()) refuse("expected a folder, got an empty path");
    const std::string shown = "\"" + dir_.string() + "\"";
    std::error_code ec;
    const fs::file_status st = fs::status(dir_, ec);
    if (fs::exists(st) && !fs::is_directory(st)) refuse(shown + " exists and is not a folder");
    if (!fs::exists(st)) {
      fs::create_directories(dir_, ec);
      if (ec) refuse("cannot create the folder " + shown + " (" + ec.message() + ")");
    }
    for (const auto& [name, is_folder] : owned) {
      const fs::path p = dir_ / name;
      const fs::file_status s = fs::status(p, ec);
      if (!fs::exists(s)) continue;
      if (is_folder && !fs::is_directory(s))
        refuse("\"" + p.string() +
               "\" exists and is not a folder; remove it or choose another "
               "output folder");
      if (!is_folder && !fs::is_regular_file(s))
        refuse("\"" + p.string() +
               "\" exists and is not a regular file; remove it or choose "
               "another output folder");
    }
    bool foreign = false;
    std::vector<fs::path> leftovers;
    fs::directory_iterator it(dir_, ec);
    if (ec) refuse("cannot read the folder " + shown + " (" + ec.message() + ")");
    for (; it != fs::directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.starts_with(output_staging_prefix))
        leftovers.push_back(it->path());
      else
        foreign = true;
    }
    if (ec) refuse("cannot read the folder " + shown + " (" + ec.message() + ")");
    if (foreign && !force && !is_grasp_transfer_results(dir_ / "results.json"))
      refuse(shown +
             " is not empty and holds no results.json of grasp_transfer; use --force "
             "to write into it: the run then replaces results.json, scenes/, figures/ and "
             "index.html there");
    for (const fs::path& p : leftovers) {
      fs::remove_all(p, ec);
      if (ec)
        refuse("cannot remove the leftover staging folder \"" + p.string() + "\" (" + ec.message() +
               ")");
    }
    staging_ = dir_ / (std::string(output_staging_prefix) + detail::temporary_file_token());
    fs::create_directory(staging_, ec);
    if (ec) refuse("cannot write into " + shown + " (" + ec.message() + ")");
    try {
      detail::write_text_file(staging_ / "write_test", "");
    } catch (const invalid_argument& e) {
      fs::remove_all(staging_, ec);
      refuse(std::string("cannot write into ") + shown + ": " + e.what());
    }
    fs::remove(staging_ / "write_test", ec);
  }

  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Removes the staging folder if the run was not committed.
  ~OutputFolder() {
    if (committed_) return;
    std::error_code ec;
    std::filesystem::remove_all(staging_, ec);
  }

  /// The output folder.
  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }
  /// Where the run writes its files (results.json, scenes/, figures/, index.html), inside dir().
  [[nodiscard]] const std::filesystem::path& staging() const noexcept { return staging_; }
  /// Whether commit() has succeeded.
  [[nodiscard]] bool committed() const noexcept { return committed_; }

  /// Puts the staged run in place: removes DIR/results.json, replaces DIR/scenes, DIR/figures and
  /// DIR/index.html by the staged ones (or removes them if none was staged), renames the staged
  /// results.json into place last, and removes the staging folder. At every moment a
  /// DIR/results.json present describes exactly the files beside it.
  /// \throws topograsp::invalid_argument naming "commit" if it was committed already or a file
  /// cannot be removed or moved (the message names it); DIR then has no results.json.
  void commit() {
    namespace fs = std::filesystem;
    if (committed_) detail::throw_invalid_argument("commit", "the run is committed already");
    std::error_code ec;
    const auto check = [&](const char* what, const fs::path& p) {
      if (ec)
        detail::throw_invalid_argument(
            "commit", std::string("cannot ") + what + " \"" + p.string() + "\" (" + ec.message() +
                          "); the new run stays in \"" + staging_.string() + "\"");
    };
    fs::remove(dir_ / "results.json", ec);
    check("remove", dir_ / "results.json");
    for (const auto& [name, is_folder] : owned) {
      if (name == "results.json") continue;
      fs::remove_all(dir_ / name, ec);
      check("remove", dir_ / name);
      if (fs::exists(staging_ / name, ec)) {
        fs::rename(staging_ / name, dir_ / name, ec);
        check("move into place", dir_ / name);
      }
    }
    if (fs::exists(staging_ / "results.json", ec)) {
      fs::rename(staging_ / "results.json", dir_ / "results.json", ec);
      check("move into place", dir_ / "results.json");
    }
    committed_ = true;
    fs::remove_all(staging_, ec);  // what is left: nothing the run owns
  }

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace topograsp
