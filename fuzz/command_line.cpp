// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: grasp_transfer's command-line parser, parse_command_line() of
// apps/grasp_transfer/command_line.hpp. The bytes are split at NUL bytes into the arguments (as the
// program would get them: a real argument never holds a NUL).
//
// - Only topograsp::invalid_argument may escape, and its message starts with the offending option:
//   one of the arguments given (or "argument" for an empty one), followed by ':' or ' '.
// - A command line that parses is consistent: unless --help, at least one object and method and
//   no repeated one, --jobs in [1, max_command_line_jobs], a shard index below the shard count, a
//   non-empty --out, --friction and --hold-fraction in range, and every transfer parameter within
//   its documented range.

#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include <grasp_transfer/command_line.hpp>
#include <topograsp/core/error.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::fuzz::fuzz_fail;

std::string describe(const std::vector<std::string_view>& args) {
  std::string s = "args (" + std::to_string(args.size()) + "):";
  for (const std::string_view a : args) s += " " + topograsp::detail::quote_argument(a);
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    std::vector<std::string_view> args;
    if (!bytes.empty()) {
      std::size_t start = 0;
      while (true) {
        const std::size_t end = bytes.find('\0', start);
        args.push_back(bytes.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) break;
        start = end + 1;
      }
    }
    // A YCB object named in --objects is loaded and its mesh decomposed into boxes while the
    // line is parsed (seconds each under the sanitizers): the fuzzer would time out on a list of
    // them. The mesh readers have fuzzers of their own (mesh_file); the parser's handling of
    // object names is fuzzed with the built-in objects.
    for (const std::string_view a : args)
      if (a.find("ycb_") != std::string_view::npos) return;
    const std::string input = describe(args);
    topograsp::CommandLine cli;
    try {
      cli = topograsp::parse_command_line(args);
    } catch (const topograsp::invalid_argument& e) {
      const std::string_view message = e.what();
      bool named = message.starts_with("argument: ");
      for (const std::string_view a : args)
        named = named || (!a.empty() && message.size() > a.size() && message.starts_with(a) &&
                          (message[a.size()] == ':' || message[a.size()] == ' '));
      if (!named)
        fuzz_fail("command_line",
                  "the error does not start with the offending option: " + std::string(message),
                  input);
      return;
    } catch (const std::exception& e) {
      fuzz_fail("command_line",
                std::string("threw ") + typeid(e).name() +
                    " (not topograsp::invalid_argument): " + e.what(),
                input);
    }
    if (cli.help) return;
    if (cli.merge) {  // merge: the shards' folders, each named, and nothing of a run
      if (cli.shards.empty()) fuzz_fail("command_line", "merge accepted without a shard", input);
      for (const std::filesystem::path& shard : cli.shards)
        if (shard.empty()) fuzz_fail("command_line", "merge accepted an empty shard name", input);
      return;
    }
    const topograsp::ExperimentOptions& x = cli.experiment;
    if (x.objects.empty() || x.methods.empty())
      fuzz_fail("command_line", "accepted with no object or no method", input);
    for (std::size_t i = 0; i < x.objects.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (x.objects[i].name == x.objects[j].name)
          fuzz_fail("command_line", "accepted a repeated object", input);
    for (std::size_t i = 0; i < x.methods.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (x.methods[i] == x.methods[j])
          fuzz_fail("command_line", "accepted a repeated method", input);
    if (x.jobs < 1 || x.jobs > topograsp::max_command_line_jobs)
      fuzz_fail("command_line", "accepted --jobs " + std::to_string(x.jobs), input);
    if (x.shard_count < 1 || x.shard_index < 0 || x.shard_index >= x.shard_count)
      fuzz_fail("command_line",
                "accepted shard " + std::to_string(x.shard_index) + " of " +
                    std::to_string(x.shard_count),
                input);
    if (cli.out.empty()) fuzz_fail("command_line", "accepted an empty --out", input);
    const double mu = x.transfer.sim.friction;
    if (!(mu == 0.0 || (mu > 0.0 && mu <= topograsp::max_command_line_friction)))
      fuzz_fail("command_line", "accepted --friction " + std::to_string(mu), input);
    const double hold = x.transfer.sim.close.hold_fraction;
    if (!(hold > 0.0 && hold <= 1.0))
      fuzz_fail("command_line", "accepted --hold-fraction " + std::to_string(hold), input);
    try {
      topograsp::validate_transfer_parameters(x.transfer);
    } catch (const topograsp::invalid_argument& e) {
      fuzz_fail("command_line",
                std::string("accepted a transfer parameter out of its range: ") + e.what(), input);
    }
  });
}
