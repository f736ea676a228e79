// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The output folder of a run: checked before any work, written through a staging folder inside
/// it, and committed so that DIR always holds a complete results.json.
///
/// The rule (docs/transfer.md): a run owns DIR/results.json, DIR/scenes/, DIR/figures/ and
/// DIR/index.html and nothing else in DIR. Everything is written into
/// DIR/.grasp_transfer-staging-<host>-<pid>-<token>/ first; commit() then notes in the staging
/// folder what it moves, replaces scenes/, figures/ and index.html entirely (removing an earlier
/// run's even where this run wrote none), and renames results.json over the old one last (one
/// atomic rename: DIR never lacks a results.json). A commit interrupted part way is finished by
/// the next run into DIR before anything else. A run that fails or is interrupted before the
/// commit leaves the previous run untouched; its staging folder is removed by the next run into
/// DIR on the same host once its process has ended. A staging folder of a process that is still
/// running (or of another host) makes the next run refuse DIR without --force: two runs never
/// write into one folder at the same time.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <grasp_transfer/file_name.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/text_file.hpp>

namespace topograsp {

/// The file in a staging folder that marks a commit under way: the entries staged, one a line.
inline constexpr std::string_view commit_marker_name = ".commit";

/// The "generator" of a results.json written by grasp_transfer (results_json): the mark by which
/// OutputFolder recognises a folder that holds an earlier run.
inline constexpr std::string_view results_generator = "topograsp grasp_transfer";

/// The version of results.json's schema (data/schemas/results.schema.json): its "schema_version".
/// 2 added it with the executable records of every transfer ("configurations", "motion",
/// "object_pose"); 3 the config's "hand" (grasp_transfer --hand); 4 the closing's grip records; 5
/// each transfer's "source_grasp" and the demonstrations of a source hand (grasp_transfer
/// --source); files without it are version 1.
inline constexpr int results_schema_version = 5;

/// The name prefix of the staging folders inside an output folder.
inline constexpr std::string_view output_staging_prefix = ".grasp_transfer-staging-";

/// What a run owns in its output folder, each replaced as a whole by commit(): results.json (the
/// main file, which marks a complete run: written last, moved into place last), then scenes/,
/// figures/ and index.html; and whether each is a folder.
inline constexpr std::array<std::pair<std::string_view, bool>, 4> output_owned{
    {{"results.json", false}, {"scenes", true}, {"figures", true}, {"index.html", false}}};
inline constexpr std::string_view results_file = output_owned[0].first;

namespace detail {

// This host's name as the staging folders carry it (file_name_part; "host" if it cannot be read).
inline std::string staging_host_name() {
  char b[256] = {};
  if (::gethostname(b, sizeof b - 1) != 0 || b[0] == '\0') return "host";
  return file_name_part(b);
}

// The name of a new staging folder: prefix, host, process id, a unique token.
inline std::string staging_folder_name() {
  return std::string(output_staging_prefix) + staging_host_name() + "-" +
         std::to_string(static_cast<long long>(::getpid())) + "-" + temporary_file_token();
}

// Whether the staging folder called \p name was left by a process of this host that has ended
// (so it may be removed): false for a running process, another host, or a name not of this form.
inline bool staging_folder_abandoned(std::string_view name) {
  name.remove_prefix(std::min(name.size(), output_staging_prefix.size()));
  const std::string host = staging_host_name() + "-";
  if (!name.starts_with(host)) return false;
  name.remove_prefix(host.size());
  long long pid = 0;
  const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), pid);
  if (ec != std::errc() || end == name.data() || pid <= 0 || *end != '-') return false;
  if (pid == static_cast<long long>(::getpid())) return false;
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace detail

/// Whether the file \p path is a results.json written by grasp_transfer: a JSON object whose
/// "generator" is results_generator, or (versions before that mark) a JSON object without a
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
  /// Checks \p dir before any work and creates DIR/.grasp_transfer-staging-<host>-<pid>-<token>/
  /// in it: DIR is created if missing; staging folders left by ended processes of this host
  /// (interrupted runs) are removed.
  /// \throws topograsp::invalid_argument naming \p argument ("dir" by default; grasp_transfer
  /// passes "--out") if \p dir is empty, exists but is not a folder, cannot be created or written,
  /// if DIR/results.json or DIR/index.html exists and is not a regular file, DIR/scenes or
  /// DIR/figures exists and is not a folder, unless \p force: if DIR holds a staging folder of a
  /// run still going (or of another host), or if DIR holds anything but staging folders and
  /// neither a results.json written by grasp_transfer (is_grasp_transfer_results) nor a staging
  /// folder of an interrupted run (which proves that grasp_transfer wrote there: an interrupted
  /// commit leaves scenes/ without results.json). Nothing in DIR is changed then, except that DIR
  /// may have been created. A commit that an ended process of this host left unfinished is
  /// finished first (finish_commit). With \p force every other staging folder is removed, but
  /// with \p keep_leftovers the staging folders of interrupted runs are kept instead (even with
  /// \p force) and listed by leftovers(), for the caller to take what it needs (grasp_transfer
  /// --resume reads their journals) before remove_leftovers().
  explicit OutputFolder(std::filesystem::path dir, bool force = false,
                        std::string_view argument = "dir", bool keep_leftovers = false)
      : dir_(std::move(dir)), argument_(argument) {
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
    for (const auto& [name, is_folder] : output_owned) {
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
    // An interrupted commit first: the new run was complete, so it is put in place.
    std::vector<fs::path> interrupted;
    for (fs::directory_iterator c(dir_, ec); !ec && c != fs::directory_iterator();
         c.increment(ec)) {
      const std::string name = c->path().filename().string();
      if (name.starts_with(output_staging_prefix) && detail::staging_folder_abandoned(name) &&
          fs::exists(c->path() / commit_marker_name, ec))
        interrupted.push_back(c->path());
    }
    for (const fs::path& p : interrupted) finish_commit(p);
    bool foreign = false;
    std::vector<fs::path> leftovers;
    std::string live;  // a staging folder of a run that may still be going
    fs::directory_iterator it(dir_, ec);
    if (ec) refuse("cannot read the folder " + shown + " (" + ec.message() + ")");
    for (; it != fs::directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (!name.starts_with(output_staging_prefix)) {
        foreign = true;
        continue;
      }
      leftovers.push_back(it->path());
      if (!detail::staging_folder_abandoned(name)) live = name;
    }
    if (ec) refuse("cannot read the folder " + shown + " (" + ec.message() + ")");
    if (!live.empty() && !force)
      refuse(shown + " holds \"" + live +
             "\", the staging folder of a run that is still going or ran on another host; give "
             "each run (each shard) its own output folder, or use --force if no other run "
             "writes there");
    if (foreign && !force && leftovers.empty() && !is_grasp_transfer_results(dir_ / results_file)) {
      std::string replaced;
      const auto& entries = output_owned;
      for (std::size_t i = 0; i < entries.size(); ++i)
        replaced += (i == 0                    ? ""
                     : i + 1 == entries.size() ? " and "
                                               : ", ") +
                    std::string(entries[i].first) + (entries[i].second ? "/" : "");
      refuse(shown +
             " is not empty and holds no results.json of grasp_transfer"
             "; use --force to write into it: the run then replaces " +
             replaced + " there");
    }
    leftovers_ = std::move(leftovers);
    if (!keep_leftovers) remove_leftovers();
    staging_ = dir_ / detail::staging_folder_name();
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

  /// Removes the staging folder if commit() was never called (and keep_staging_on_failure()
  /// was not). After a commit() that failed part way the staging folder stays: it holds the new
  /// run (the message of commit()'s exception says where).
  ~OutputFolder() {
    if (committing_ || keep_staging_) return;
    std::error_code ec;
    std::filesystem::remove_all(staging_, ec);
  }

  /// Keeps the staging folder if the run is not committed (the destructor then leaves it, as a
  /// killed run does): for a run that journals its progress there, so that a failed run can be
  /// resumed. The next run into dir() removes it or, resuming, takes it over.
  void keep_staging_on_failure() noexcept { keep_staging_ = true; }

  /// The staging folders of interrupted runs that the constructor kept (keep_leftovers).
  [[nodiscard]] const std::vector<std::filesystem::path>& leftovers() const noexcept {
    return leftovers_;
  }
  /// Removes the staging folders of leftovers().
  /// \throws topograsp::invalid_argument naming the constructor's argument if one cannot be
  /// removed.
  void remove_leftovers() {
    std::error_code ec;
    for (const std::filesystem::path& p : leftovers_) {
      std::filesystem::remove_all(p, ec);
      if (ec)
        detail::throw_invalid_argument(argument_, "cannot remove the leftover staging folder \"" +
                                                      p.string() + "\" (" + ec.message() + ")");
    }
    leftovers_.clear();
  }

  /// The output folder.
  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }
  /// Where the run writes its files (results.json, scenes/, figures/, index.html), inside dir().
  [[nodiscard]] const std::filesystem::path& staging() const noexcept { return staging_; }
  /// Whether commit() has succeeded.
  [[nodiscard]] bool committed() const noexcept { return committed_; }
  /// Whether commit() was called (it may have failed part way; the next run into DIR finishes it).
  [[nodiscard]] bool commit_started() const noexcept { return committing_; }

  /// Puts the staged run in place: notes the staged entries in the staging folder
  /// (commit_marker_name), replaces DIR/scenes, DIR/figures and DIR/index.html by the staged ones
  /// (or removes them if none was staged), renames the staged results.json over DIR/results.json
  /// last (atomically: DIR always has one), and removes the staging folder. A commit interrupted
  /// part way (the process killed) is finished by the next OutputFolder on DIR.
  /// \throws topograsp::invalid_argument naming "commit" if it was committed already or a file
  /// cannot be written, removed or moved (the message names it and where the new run stays).
  void commit() {
    namespace fs = std::filesystem;
    if (committing_) detail::throw_invalid_argument("commit", "commit() was called already");
    committing_ = true;
    std::string staged;
    std::error_code ec;
    for (const auto& [name, is_folder] : output_owned)
      if (fs::exists(staging_ / name, ec)) staged += std::string(name) + "\n";
    try {
      detail::write_text_file(staging_ / commit_marker_name, staged);
    } catch (const invalid_argument& e) {
      detail::throw_invalid_argument(
          "commit", std::string(e.what()) + "; the new run stays in \"" + staging_.string() + "\"");
    }
    finish_commit(staging_);
    committed_ = true;
  }

  /// Finishes the commit noted in the staging folder \p staging (commit_marker_name): each
  /// entry the marker names that is still in \p staging replaces DIR's, each entry it does not
  /// name is removed from DIR, the main file is renamed in last, and \p staging is removed. Each
  /// step can be taken again, so an interrupted commit is finished by calling this once more.
  /// \throws topograsp::invalid_argument naming "commit" if a file cannot be read, removed or
  /// moved (the message names it).
  void finish_commit(const std::filesystem::path& staging) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto check = [&](const char* what, const fs::path& p) {
      if (ec)
        detail::throw_invalid_argument(
            "commit", std::string("cannot ") + what + " \"" + p.string() + "\" (" + ec.message() +
                          "); the new run stays in \"" + staging.string() + "\"");
    };
    std::ifstream marker(staging / commit_marker_name, std::ios::binary);
    if (!marker) {
      ec = std::make_error_code(std::errc::io_error);
      check("read", staging / commit_marker_name);
    }
    std::vector<std::string> staged;
    for (std::string line; std::getline(marker, line);) staged.push_back(line);
    const auto was_staged = [&](std::string_view name) {
      return std::find(staged.begin(), staged.end(), name) != staged.end();
    };
    for (const auto& [name, is_folder] : output_owned) {
      if (name == results_file) continue;
      const bool in_staging = fs::exists(staging / name, ec);
      if (in_staging || !was_staged(name)) {  // else it was moved in already
        fs::remove_all(dir_ / name, ec);
        check("remove", dir_ / name);
      }
      if (in_staging) {
        fs::rename(staging / name, dir_ / name, ec);
        check("move into place", dir_ / name);
      }
    }
    const fs::path main = dir_ / results_file;
    if (fs::exists(staging / results_file, ec)) {
      fs::rename(staging / results_file, main, ec);  // replaces the old one at once
      check("move into place", main);
    } else if (!was_staged(results_file)) {
      fs::remove(main, ec);  // a run without a main file leaves none of an earlier run
      check("remove", main);
    }
    fs::remove_all(staging, ec);  // what is left: nothing the run owns
  }

 private:
  std::filesystem::path dir_;
  std::string argument_;
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> leftovers_;
  bool committed_ = false;
  bool committing_ = false;  // commit() was called
  bool keep_staging_ = false;
};

}  // namespace topograsp
