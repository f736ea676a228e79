// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The journal of a grasp-transfer run, so that an interrupted run can be resumed
/// (grasp_transfer --resume), and the merge of the results of a run's shards (grasp_transfer
/// merge). See docs/transfer.md.
///
/// The journal is a text file of JSON lines in the run's staging folder: the first line is
/// {"config": ...} (results_config), every further line one finished hypothesis,
/// {"object": name, "id": n, "records": [...]} (hypothesis_records), appended and flushed after
/// the hypothesis's scene files were written. A run killed while writing a line leaves that line
/// incomplete; reading stops there, so what was read is always whole.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <grasp_transfer/results.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// The journal's file name inside a staging folder.
inline constexpr std::string_view journal_file_name = "journal.jsonl";

/// One finished hypothesis of a journal.
struct JournalEntry {
  std::string object;
  int id = 0;
  std::vector<Json> records;  ///< its grasp records (hypothesis_records); may be empty
};

namespace detail {

// The first key at which two configs differ (by their JSON text), ignoring \p ignored; empty if
// none.
inline std::string first_config_difference(const Json& a, const Json& b,
                                           const std::vector<std::string>& ignored) {
  const auto& oa = a.as_object();
  const auto& ob = b.as_object();
  const auto find = [](const Json::Object& o, const std::string& key) -> const Json* {
    for (const auto& [k, v] : o)
      if (k == key) return &v;
    return nullptr;
  };
  for (const Json::Object* o : {&oa, &ob})
    for (const auto& [key, value] : *o) {
      if (std::find(ignored.begin(), ignored.end(), key) != ignored.end()) continue;
      const Json *x = find(oa, key), *y = find(ob, key);
      if (x == nullptr || y == nullptr || x->dump(0) != y->dump(0)) return key;
    }
  return {};
}

inline std::string read_text_file(const std::filesystem::path& path, std::string_view argument) {
  std::ifstream f(path, std::ios::binary);
  if (!f) detail::throw_invalid_argument(argument, "cannot read \"" + path.string() + "\"");
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) detail::throw_invalid_argument(argument, "cannot read \"" + path.string() + "\"");
  return text;
}

}  // namespace detail

/// Appends finished hypotheses to a journal file.
class ResultsJournal {
 public:
  /// Creates (or truncates) the journal \p path and writes its config line.
  /// \throws topograsp::invalid_argument naming "journal" if the file cannot be written.
  ResultsJournal(std::filesystem::path path, const Json& config)
      : path_(std::move(path)), out_(path_, std::ios::binary | std::ios::trunc) {
    Json first = Json::object();
    first.set("config", config);
    write_line(first);
  }

  /// Appends \p entry as one line and flushes it.
  /// \throws topograsp::invalid_argument naming "journal" if it cannot be written (disk full).
  void append(const JournalEntry& entry) {
    Json line = Json::object();
    line.set("object", entry.object);
    line.set("id", entry.id);
    Json::Array records(entry.records.begin(), entry.records.end());
    line.set("records", Json(std::move(records)));
    write_line(line);
  }

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

 private:
  void write_line(const Json& j) {
    out_ << j.dump(0) << '\n';
    out_.flush();
    if (!out_) detail::throw_invalid_argument("journal", "cannot write \"" + path_.string() + "\"");
  }

  std::filesystem::path path_;
  std::ofstream out_;
};

namespace detail {

// The hypothesis journalled on line \p line_number of the journal \p path: {"object": name,
// "id": a whole number in [0, 2^31), "records": [grasp records of that object and id, each with
// a "method" name]}. Throws naming "--resume", the file and the line otherwise.
inline JournalEntry journal_entry(const Json& line, const std::filesystem::path& path,
                                  int line_number) {
  const auto refuse = [&](const std::string& problem) {
    throw_invalid_argument("--resume", file_line_message(path.string(), line_number, problem) +
                                           " (not a line grasp_transfer writes; start afresh "
                                           "without --resume)");
  };
  const auto whole = [](const Json& j) {
    return j.is_number() && j.as_number() >= 0.0 && j.as_number() < 2147483648.0 &&
           j.as_number() == std::floor(j.as_number());
  };
  if (!line.is_object()) refuse("expected an object");
  for (const char* key : {"object", "id", "records"})
    if (!line.contains(key)) refuse(std::string("no \"") + key + "\"");
  if (!line.at("object").is_string()) refuse("\"object\" is not a name");
  if (!whole(line.at("id"))) refuse("\"id\" is not a whole number in [0, 2^31)");
  if (!line.at("records").is_array()) refuse("\"records\" is not a list");
  JournalEntry e;
  e.object = line.at("object").as_string();
  e.id = static_cast<int>(line.at("id").as_number());
  for (const Json& r : line.at("records").as_array()) {
    if (!r.is_object() || !r.contains("object") || !r.contains("id") || !r.contains("method") ||
        !r.at("method").is_string())
      refuse("a record without its object, id and method");
    if (!r.at("object").is_string() || r.at("object").as_string() != e.object ||
        !r.at("id").is_number() || r.at("id").as_number() != static_cast<double>(e.id))
      refuse("a record of another hypothesis");
    e.records.push_back(r);
  }
  return e;
}

}  // namespace detail

/// The finished hypotheses of the journal \p path, written by a run whose config is \p config
/// (every key but "jobs" must be equal). Reading stops at the first line that is not complete
/// JSON (a run killed while writing it).
/// \throws topograsp::invalid_argument naming "--resume" if the file cannot be read, its first
/// line is not a config, the config differs (the message names the first key that does), or a
/// hypothesis's line is not one grasp_transfer writes (journal_entry: the message names the file
/// and the line).
[[nodiscard]] inline std::vector<JournalEntry> read_journal(const std::filesystem::path& path,
                                                            const Json& config) {
  const std::string text = detail::read_text_file(path, "--resume");
  std::vector<JournalEntry> out;
  std::size_t begin = 0;
  int line_number = 0;
  bool first = true;
  while (begin < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) break;  // the last line was not finished
    Json line;
    try {
      line = Json::parse(std::string_view(text).substr(begin, end - begin));
    } catch (const invalid_argument&) {
      break;
    }
    begin = end + 1;
    if (first) {
      if (!line.is_object() || !line.contains("config") || !line.at("config").is_object())
        detail::throw_invalid_argument("--resume",
                                       "\"" + path.string() + "\" does not start with a config");
      const std::string key = detail::first_config_difference(line.at("config"), config, {"jobs"});
      if (!key.empty())
        detail::throw_invalid_argument(
            "--resume",
            "\"" + path.string() + "\" was written by a run with another \"" + key + "\" (" +
                (line.at("config").contains(key) ? line.at("config").at(key).dump(0)
                                                 : std::string("none")) +
                " there, " + (config.contains(key) ? config.at(key).dump(0) : std::string("none")) +
                " now); resume with the same options and the same version of grasp_transfer, or "
                "start afresh without --resume");
      first = false;
      continue;
    }
    out.push_back(detail::journal_entry(line, path, line_number));
  }
  return out;
}

/// The results.json of a whole run from those of its shards (\p shards, as read from each shard's
/// output folder; any order): every grasp record once, the objects' hypotheses summed, every
/// summary computed again (results_document), and the config of the shards with "shard" "1/1"
/// (and the first shard's "jobs"). Equal to the document of the unsharded run but for the
/// timings ("plan_ms") and "jobs".
/// \throws topograsp::invalid_argument naming "shards" if there are none, one is not a
/// results.json of grasp_transfer or was written with another results_schema_version, their
/// configs differ in anything but "shard" and "jobs" (the
/// message names the key), or the shards are not 1/N to N/N of one N, each once.
[[nodiscard]] inline Json merge_results(const std::vector<Json>& shards) {
  if (shards.empty()) detail::throw_invalid_argument("shards", "expected at least one");
  for (const Json& s : shards)
    if (!s.is_object() || !s.contains("generator") || !s.at("generator").is_string() ||
        s.at("generator").as_string() != results_generator || !s.contains("config"))
      detail::throw_invalid_argument("shards", "expected results.json files of grasp_transfer");
  for (const Json& s : shards) {
    const int version = s.contains("schema_version") && s.at("schema_version").is_number()
                            ? static_cast<int>(s.at("schema_version").as_number())
                            : 1;
    if (version != results_schema_version)
      detail::throw_invalid_argument("shards", "a shard was written with results schema " +
                                                   std::to_string(version) +
                                                   " and this grasp_transfer writes " +
                                                   std::to_string(results_schema_version) +
                                                   ": run the shards again with this version");
  }
  const Json& config = shards.front().at("config");
  int count = 0;
  std::vector<int> seen;
  for (const Json& s : shards) {
    const std::string key =
        detail::first_config_difference(s.at("config"), config, {"shard", "jobs"});
    if (!key.empty())
      detail::throw_invalid_argument("shards", "the shards were run with different \"" + key +
                                                   "\" (" + config.at(key).dump(0) + " and " +
                                                   s.at("config").at(key).dump(0) + ")");
    const std::string shard = s.at("config").at("shard").as_string();
    int k = 0, n = 0;
    const char* const end = shard.data() + shard.size();
    const auto [slash, e1] = std::from_chars(shard.data(), end, k);
    const auto [last, e2] = slash != end && *slash == '/' ? std::from_chars(slash + 1, end, n)
                                                          : std::from_chars_result{};
    if (e1 != std::errc() || e2 != std::errc() || last != end || k < 1 || k > n)
      detail::throw_invalid_argument("shards", "a shard \"" + shard + "\" is not K/N");
    if (count == 0) count = n;
    if (n != count)
      detail::throw_invalid_argument("shards", "shards of " + std::to_string(count) + " and of " +
                                                   std::to_string(n) + " parts");
    if (std::find(seen.begin(), seen.end(), k) != seen.end())
      detail::throw_invalid_argument("shards", "shard " + shard + " is given twice");
    seen.push_back(k);
  }
  if (static_cast<int>(seen.size()) != count) {
    std::string missing;
    for (int k = 1; k <= count; ++k)
      if (std::find(seen.begin(), seen.end(), k) == seen.end())
        missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(count);
    detail::throw_invalid_argument("shards", "shard " + missing + " is missing");
  }
  std::vector<ObjectRecords> objects;
  for (const Json& name : config.at("objects").as_array())
    objects.push_back({name.as_string(), 0, {}});
  for (const Json& s : shards) {
    for (const Json& o : s.at("objects").as_array())
      for (ObjectRecords& r : objects)
        if (r.name == o.at("name").as_string())
          r.hypotheses += static_cast<int>(o.at("hypotheses").as_number());
    for (const Json& g : s.at("grasps").as_array())
      for (ObjectRecords& r : objects)
        if (r.name == g.at("object").as_string()) r.grasps.push_back(g);
  }
  Json merged = config;
  merged.set("shard", "1/1");
  return results_document(merged, std::move(objects));
}

}  // namespace topograsp
