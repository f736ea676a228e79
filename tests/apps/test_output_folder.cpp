// SPDX-License-Identifier: BSD-3-Clause
#include <stdlib.h>  // mkdtemp
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include <grasp_transfer/output_folder.hpp>
#include <topograsp/io/text_file.hpp>

#include "support/throws.hpp"

using namespace topograsp;
namespace fs = std::filesystem;

namespace {

// The id of a process of this host that has ended (a child that exited and was reaped).
pid_t ended_process() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  REQUIRE(child > 0);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  return child;
}

// The name of a staging folder of process \p pid on this host.
std::string staging_name_of(pid_t pid) {
  return std::string(output_staging_prefix) + detail::staging_host_name() + "-" +
         std::to_string(static_cast<long long>(pid)) + "-0000000000000000-0";
}

// A temporary directory removed at the end of the scope.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::string templ = (fs::temp_directory_path() / "topograsp-out-XXXXXX").string();
    REQUIRE(mkdtemp(templ.data()) != nullptr);
    path = templ;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void put(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// The names in folder p, sorted.
std::vector<std::string> listing(const fs::path& p) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(p)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string results_text(const std::string& run) {
  return "{\"generator\": \"" + std::string(results_generator) + "\", \"run\": \"" + run + "\"}\n";
}

// A run into dir: results.json and the given scenes (and a figure if figures), committed.
void run_into(const fs::path& dir, const std::string& run, std::vector<std::string> scenes,
              bool figures, bool force = false) {
  OutputFolder out(dir, force);
  for (const std::string& s : scenes)
    put(out.staging() / "scenes" / s, run);  // the run's scene files
  if (figures) {
    put(out.staging() / "figures" / "f.svg", run);
    put(out.staging() / "index.html", run);
  }
  detail::write_text_file(out.staging() / "results.json", results_text(run));
  CHECK_FALSE(out.commit_started());
  out.commit();
  CHECK(out.commit_started());
  CHECK(out.committed());
}

}  // namespace

TEST_CASE("write_text_file replaces a file whole, through a temporary beside it", "[io][output]") {
  const ScratchDir d;
  const fs::path f = d.path / "a.txt";
  detail::write_text_file(f, "first");
  CHECK(slurp(f) == "first");
  detail::write_text_file(f, "second, longer");
  CHECK(slurp(f) == "second, longer");
  detail::write_text_file(f, "");
  CHECK(slurp(f).empty());
  CHECK(listing(d.path) == std::vector<std::string>{"a.txt"});  // no temporary left
}

TEST_CASE("a failed write leaves the previous file as it was", "[io][output][bad-input]") {
  const ScratchDir d;
  SECTION("the target is a folder") {
    fs::create_directory(d.path / "x");
    put(d.path / "x" / "inside", "kept");
    CHECK_THROWS_WITH(
        detail::write_text_file(d.path / "x", "new"),
        Catch::StartsWith("path: cannot put the written file in place") && Catch::Contains("/x\""));
    CHECK(slurp(d.path / "x" / "inside") == "kept");
    CHECK(listing(d.path) == std::vector<std::string>{"x"});
  }
  SECTION("the parent is a regular file") {
    put(d.path / "file", "kept");
    CHECK_THROWS_WITH(detail::write_text_file(d.path / "file" / "a.txt", "new"),
                      Catch::StartsWith("path: cannot create a temporary file"));
    CHECK(slurp(d.path / "file") == "kept");
  }
  SECTION("the write fails part way (a file-size limit, as a full disk)") {
    // RLIMIT_FSIZE holds for root too. The old file is short; the new text exceeds the limit.
    const fs::path f = d.path / "results.json";
    const std::string old = "{\"old\": true}\n";
    detail::write_text_file(f, old);
    rlimit saved{};
    REQUIRE(getrlimit(RLIMIT_FSIZE, &saved) == 0);
    const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved;
    small.rlim_cur = 4096;
    REQUIRE(setrlimit(RLIMIT_FSIZE, &small) == 0);
    std::string message;
    try {
      detail::write_text_file(f, std::string(100000, 'x'));
    } catch (const topograsp::invalid_argument& e) {
      message = e.what();
    }
    REQUIRE(setrlimit(RLIMIT_FSIZE, &saved) == 0);
    (void)std::signal(SIGXFSZ, previous_handler);
    INFO(message);
    CHECK_THAT(message, Catch::StartsWith("path: cannot write") &&
                            Catch::Contains("previous file there is unchanged"));
    CHECK(slurp(f) == old);  // byte-identical
    CHECK(listing(d.path) == std::vector<std::string>{"results.json"});
  }
}

TEST_CASE("an output folder is staged and committed, results.json last", "[io][output]") {
  const ScratchDir d;
  const fs::path dir = d.path / "new" / "out";  // created
  run_into(dir, "one", {"hammer_0_human.xml", "hammer_1_human.xml"}, true);
  CHECK(listing(dir) ==
        std::vector<std::string>{"figures", "index.html", "results.json", "scenes"});
  CHECK(listing(dir / "scenes") ==
        std::vector<std::string>{"hammer_0_human.xml", "hammer_1_human.xml"});
  CHECK(is_grasp_transfer_results(dir / "results.json"));

  SECTION("a second run replaces what the run owns, and only that") {
    put(dir / "notes.txt", "mine");
    run_into(dir, "two", {"bottle_3_human.xml"}, false);
    // No stale scene or figure of the first run beside the second's results.json.
    CHECK(listing(dir) == std::vector<std::string>{"notes.txt", "results.json", "scenes"});
    CHECK(listing(dir / "scenes") == std::vector<std::string>{"bottle_3_human.xml"});
    CHECK(slurp(dir / "results.json") == results_text("two"));
    CHECK(slurp(dir / "notes.txt") == "mine");
  }
  SECTION("a run that is not committed leaves the previous run untouched") {
    {
      OutputFolder out(dir);
      put(out.staging() / "scenes" / "bottle_3_human.xml", "two");
      detail::write_text_file(out.staging() / "results.json", results_text("two"));
      // ... the computation fails here: no commit
    }
    CHECK(listing(dir) ==
          std::vector<std::string>{"figures", "index.html", "results.json", "scenes"});
    CHECK(slurp(dir / "results.json") == results_text("one"));
    CHECK(listing(dir / "scenes").size() == 2);
  }
  SECTION("the staging folder of an interrupted run is removed by the next run") {
    const fs::path leftover = dir / staging_name_of(ended_process());
    put(leftover / "scenes" / "hammer_9_human.xml", "interrupted");
    CHECK(slurp(dir / "results.json") == results_text("one"));  // the previous run still there
    OutputFolder out(dir);
    CHECK_FALSE(fs::exists(leftover));
    CHECK(out.staging().parent_path() == dir);
    CHECK(fs::is_directory(out.staging()));
    out.commit();
    CHECK_FALSE(fs::exists(out.staging()));
    // Nothing staged: the run owns results.json, scenes, figures and index.html, now gone.
    CHECK(listing(dir).empty());
    CHECK_THROWS_WITH(out.commit(), Catch::StartsWith("commit: commit() was called already"));
  }
  SECTION("an interrupted commit (scenes, no results.json) is still recognised as a run") {
    fs::remove(dir / "results.json");
    put(dir / staging_name_of(ended_process()) / "results.json", results_text("two"));
    OutputFolder out(dir);  // no --force needed: the staging folder proves grasp_transfer wrote
    put(out.staging() / "scenes" / "bottle_3_human.xml", "three");
    detail::write_text_file(out.staging() / "results.json", results_text("three"));
    out.commit();
    CHECK(listing(dir) == std::vector<std::string>{"results.json", "scenes"});
  }
  SECTION("a commit killed part way is finished by the next run, and results.json never missing") {
    // The state a kill leaves between the commit's renames: the new scenes moved in, the
    // figures of run one still to be removed, the new results.json not yet renamed over the old.
    const fs::path killed = dir / staging_name_of(ended_process());
    put(killed / std::string(commit_marker_name), "results.json\nscenes\n");
    fs::remove_all(dir / "scenes");
    put(dir / "scenes" / "bottle_3_human.xml", "two");
    put(killed / "results.json", results_text("two"));
    CHECK(slurp(dir / "results.json") == results_text("one"));  // the old one stays meanwhile
    OutputFolder out(dir);
    CHECK_FALSE(fs::exists(killed));
    CHECK(slurp(dir / "results.json") == results_text("two"));
    CHECK(listing(dir) ==
          std::vector<std::string>{out.staging().filename().string(), "results.json", "scenes"});
    CHECK(listing(dir / "scenes") == std::vector<std::string>{"bottle_3_human.xml"});
  }
  SECTION("a commit under way in a running process is not finished by another") {
    const fs::path live = dir / staging_name_of(::getpid());
    put(live / std::string(commit_marker_name), "results.json\n");
    put(live / "results.json", results_text("two"));
    CHECK_THROWS_WITH(OutputFolder(dir), Catch::Contains("still going"));
    CHECK(slurp(dir / "results.json") == results_text("one"));
  }
  SECTION("--resume --force keeps the interrupted runs' staging folders for their journals") {
    const fs::path leftover = dir / staging_name_of(ended_process());
    put(leftover / "journal.jsonl", "{}\n");
    OutputFolder out(dir, true, "--out", true);
    REQUIRE(out.leftovers().size() == 1);
    CHECK(out.leftovers().front() == leftover);
    CHECK(fs::exists(leftover / "journal.jsonl"));
    out.remove_leftovers();
    CHECK_FALSE(fs::exists(leftover));
  }
  SECTION("a staging folder of a run still going is never removed without --force") {
    // This process is running: its staging folder stands for a concurrent run (a shard given
    // the same --out), which another run must not delete.
    const fs::path live = dir / staging_name_of(::getpid());
    put(live / "scenes" / "x.xml", "live");
    test::check_throws_naming([&] { OutputFolder out(dir); }, "dir");
    CHECK_THROWS_WITH(OutputFolder(dir),
                      Catch::Contains("still going") && Catch::Contains("its own output folder"));
    CHECK(fs::exists(live / "scenes" / "x.xml"));
    // Another host's staging folder: its process cannot be checked from here.
    const fs::path remote = dir / (std::string(output_staging_prefix) + "otherhost-1-x");
    fs::remove_all(live);
    put(remote / "a", "remote");
    CHECK_THROWS_AS(OutputFolder(dir), invalid_argument);
    OutputFolder forced(dir, true);
    CHECK_FALSE(fs::exists(remote));
  }
}

TEST_CASE("an output folder is checked before any work", "[io][output][bad-input]") {
  const ScratchDir d;
  const auto refused = [](const fs::path& dir, bool force = false) -> std::string {
    try {
      const OutputFolder out(dir, force, "--out");
    } catch (const topograsp::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(refused(""), Catch::StartsWith("--out: expected a folder"));
  put(d.path / "file", "x");
  CHECK_THAT(refused(d.path / "file"),
             Catch::StartsWith("--out:") && Catch::Contains("not a folder"));
  CHECK_THAT(refused(d.path / "file" / "out"), Catch::StartsWith("--out: cannot create"));
  CHECK(slurp(d.path / "file") == "x");

  SECTION("results.json or index.html that is not a file, scenes or figures that is not a folder") {
    for (const char* entry : {"results.json", "index.html"}) {
      const fs::path dir = d.path / (std::string("out-") + entry);
      fs::create_directories(dir / entry);
      INFO(entry);
      CHECK_THAT(refused(dir, true),
                 Catch::StartsWith("--out:") &&
                     Catch::Contains(std::string(entry) + "\" exists and is "
                                                          "not a regular file"));
      CHECK(listing(dir) == std::vector<std::string>{entry});  // nothing staged
    }
    for (const char* entry : {"scenes", "figures"}) {
      const fs::path dir = d.path / (std::string("out-") + entry);
      put(dir / entry, "a file");
      INFO(entry);
      CHECK_THAT(refused(dir, true), Catch::Contains(std::string(entry) + "\" exists and is not a "
                                                                          "folder"));
    }
  }
  SECTION("a folder with other files is refused unless force") {
    const fs::path dir = d.path / "photos";
    put(dir / "holiday.jpg", "jpg");
    CHECK_THAT(refused(dir),
               Catch::StartsWith("--out:") && Catch::Contains("holds no results.json of "
                                                              "grasp_transfer; use --force"));
    CHECK(listing(dir) == std::vector<std::string>{"holiday.jpg"});
    // A results.json that is not ours does not make it ours.
    put(dir / "results.json", "{\"generator\": \"someone else\"}");
    CHECK_THAT(refused(dir), Catch::Contains("use --force"));
    put(dir / "results.json", "{\"config\": {}, \"objects\": [], \"grasp\": []}");
    CHECK_THAT(refused(dir), Catch::Contains("use --force"));
    put(dir / "results.json", "not json");
    CHECK_FALSE(is_grasp_transfer_results(dir / "results.json"));
    CHECK_THAT(refused(dir), Catch::Contains("use --force"));
    CHECK(refused(dir, true).empty());
    run_into(dir, "forced", {"a_0_human.xml"}, false, true);
    CHECK(slurp(dir / "holiday.jpg") == "jpg");
    CHECK(is_grasp_transfer_results(dir / "results.json"));
    CHECK(refused(dir).empty());  // now it holds a run of ours
  }
  SECTION("a results.json of an earlier version (no generator) is recognised") {
    const fs::path dir = d.path / "earlier";
    put(dir / "results.json", "{\"config\": {\"seed\": \"1\"}, \"objects\": [], \"grasps\": []}");
    put(dir / "scenes" / "hammer_0_human.xml", "<mujoco/>");
    CHECK(is_grasp_transfer_results(dir / "results.json"));
    CHECK(refused(dir).empty());
  }
  SECTION("an empty folder is fine") {
    fs::create_directory(d.path / "empty");
    CHECK(refused(d.path / "empty").empty());
    CHECK(listing(d.path / "empty").empty());  // the unused staging folder was removed
  }
}
