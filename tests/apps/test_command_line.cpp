// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/command_line.hpp>

using namespace topograsp;

namespace {

CommandLine parse(std::initializer_list<std::string_view> args) {
  const std::vector<std::string_view> v(args);
  return parse_command_line(v);
}

// The message of the topograsp::invalid_argument that parsing args throws ("" if none).
std::string error_of(std::initializer_list<std::string_view> args) {
  try {
    (void)parse(args);
  } catch (const topograsp::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the command line's defaults and values", "[io][command_line]") {
  const CommandLine d = parse({});
  CHECK(d.out == "grasp_transfer_out");
  CHECK_FALSE((d.quiet || d.figures || d.force || d.help));
  REQUIRE(d.experiment.objects.size() == 2);
  CHECK(d.experiment.objects[0].name == "hammer");
  CHECK(d.experiment.objects[1].name == "bottle");
  CHECK(d.experiment.methods ==
        std::vector<TransferMethod>{TransferMethod::topological, TransferMethod::autoclose,
                                    TransferMethod::transplant, TransferMethod::fingertip,
                                    TransferMethod::virtual_finger});
  CHECK(d.experiment.jobs == 1);
  CHECK(d.experiment.seed == 1);

  const CommandLine c = parse({"--objects",
                               "bottle",
                               "--methods",
                               "fingertip,topological",
                               "--out",
                               "x/y",
                               "--jobs",
                               "72",
                               "--seed",
                               "18446744073709551615",
                               "--shard",
                               "2/3",
                               "--max-hypotheses",
                               "0",
                               "--winding-reference",
                               "nearest_point",
                               "--set",
                               "final_approach=0.1",
                               "--set",
                               "line_precision_end=0",
                               "--figures",
                               "--quiet",
                               "--force"});
  REQUIRE(c.experiment.objects.size() == 1);
  CHECK(c.experiment.objects[0].name == "bottle");
  CHECK(c.experiment.methods ==
        std::vector<TransferMethod>{TransferMethod::fingertip, TransferMethod::topological});
  CHECK(c.out == "x/y");
  CHECK(c.experiment.jobs == 72);
  CHECK(c.experiment.seed == 18446744073709551615ull);
  CHECK(c.experiment.shard_index == 1);
  CHECK(c.experiment.shard_count == 3);
  CHECK(c.experiment.transfer.winding_reference == WindingReference::nearest_point);
  CHECK(c.experiment.transfer.final_approach == 0.1);
  CHECK(c.experiment.transfer.line_precision_end == 0.0);
  CHECK((c.figures && c.quiet && c.force && !c.help));

  // --help returns at once, whatever follows.
  CHECK(parse({"--help", "--bogus"}).help);
  CHECK(parse({"--jobs", "2", "-h"}).help);
}

TEST_CASE("the option --friction sets one coefficient for every pair; the default is the table",
          "[io][command_line]") {
  CHECK(parse({}).experiment.transfer.sim.friction == 0.0);
  CHECK(parse({"--friction", "0.3"}).experiment.transfer.sim.friction == 0.3);
  CHECK(parse({"--friction", "10"}).experiment.transfer.sim.friction == 10.0);
}

TEST_CASE("the option --hold-fraction sets the robot hand's hold fraction", "[io][command_line]") {
  CHECK(parse({}).experiment.transfer.sim.close.hold_fraction == 0.5);
  CHECK(parse({"--hold-fraction", "0.25"}).experiment.transfer.sim.close.hold_fraction == 0.25);
  CHECK(parse({"--hold-fraction", "1"}).experiment.transfer.sim.close.hold_fraction == 1.0);
  CHECK(parse({"--hold-fraction", "0.25"}).experiment.transfer.sim.human_hold_fraction == 1.0);
  for (const std::string_view f : {"0", "-0.5", "1.01", "nan", "inf", "half"}) {
    INFO(f);
    CHECK_THAT(error_of({"--hold-fraction", f}), Catch::StartsWith("--hold-fraction: "));
  }
  CHECK_THAT(error_of({"--hold-fraction", "0.5", "--hold-fraction", "0.3"}),
             Catch::StartsWith("--hold-fraction: given twice"));
}

TEST_CASE("the flag --every-test runs the whole stability suite on every grasp",
          "[io][command_line]") {
  CHECK_FALSE(parse({}).experiment.transfer.sim.stability.every_test);
  CHECK(parse({"--every-test"}).experiment.transfer.sim.stability.every_test);
  CHECK_THAT(error_of({"--every-test=1"}), Catch::StartsWith("--every-test=1: unknown option"));
}

TEST_CASE("the options --hypotheses and --closing choose the demonstrations' rule and closing",
          "[io][command_line]") {
  // The default: the power grip's hypotheses, closed on the held object, balanced.
  const CommandLine d = parse({});
  CHECK(d.experiment.hypotheses == HypothesisRule::power);
  CHECK(d.experiment.transfer.sim.close.hold_object);
  CHECK(d.experiment.transfer.sim.close.balanced_hold);
  CHECK(d.experiment.transfer.sim.palm_first);
  CHECK(parse({"--hypotheses", "box"}).experiment.hypotheses == HypothesisRule::box);
  CHECK(parse({"--hypotheses", "demonstrator"}).experiment.hypotheses ==
        HypothesisRule::demonstrator);
  CHECK(to_string(HypothesisRule::power) == "power");
  // held and balanced share the protocol; balanced also holds with balanced torques.
  for (const char* closing : {"held", "balanced"}) {
    INFO(closing);
    const CommandLine cli = parse({"--closing", closing});
    const GraspSimOptions& sim = cli.experiment.transfer.sim;
    CHECK(sim.close.hold_object);
    CHECK(sim.close.release_steps == 15);
    CHECK(sim.palm_first);
    CHECK(sim.close.proximal_first);
    CHECK(sim.close.balanced_hold == (std::string_view(closing) == "balanced"));
  }
  // free: the paper's protocol, nothing of the held closing left over from the default.
  const GraspSimOptions free = parse({"--closing", "free"}).experiment.transfer.sim;
  CHECK_FALSE(free.close.hold_object);
  CHECK(free.close.release_steps == 0);
  CHECK_FALSE(free.close.proximal_first);
  CHECK_FALSE(free.close.balanced_hold);
  CHECK_FALSE(free.palm_first);
  CHECK_THAT(error_of({"--closing", "fixed"}),
             Catch::StartsWith("--closing: expected free, held or balanced"));
  CHECK_THAT(error_of({"--hypotheses", "many"}), Catch::StartsWith("--hypotheses: "));
  CHECK_THAT(error_of({"--closing", "held", "--closing", "free"}),
             Catch::StartsWith("--closing: given twice"));
}

TEST_CASE("the option --setting chooses the hand or the arm setting", "[io][command_line]") {
  CHECK_FALSE(parse({}).experiment.arm_setting);
  CHECK_FALSE(parse({"--setting", "hand"}).experiment.arm_setting);
  CHECK(parse({"--setting", "arm"}).experiment.arm_setting);
  CHECK_THAT(error_of({"--setting", "paper"}),
             Catch::StartsWith("--setting: expected hand or arm, got \"paper\""));
  CHECK_THAT(error_of({"--setting", "arm", "--setting", "hand"}),
             Catch::StartsWith("--setting: given twice"));
}

TEST_CASE("the option --hand picks one of the program's hands, the first by default",
          "[io][command_line]") {
  const std::vector<std::string_view> hands{"sdh", "allegro", "shadow"};
  const auto parse_hands = [&](std::initializer_list<std::string_view> args) {
    const std::vector<std::string_view> v(args);
    return parse_command_line(v, false, hands);
  };
  CHECK(parse({}).hand == "sdh");  // a program that names no hands: the SDH's
  CHECK(parse_hands({}).hand == "sdh");
  CHECK(parse_hands({"--hand", "shadow"}).hand == "shadow");
  const std::vector<std::string_view> gripper_only{"gripper"};
  CHECK(parse_command_line(std::vector<std::string_view>{}, false, gripper_only).hand == "gripper");
  CHECK_THROWS_WITH(parse_hands({"--hand", "barrett"}),
                    "--hand: no hand \"barrett\" in this program (sdh, allegro, shadow)");
  CHECK_THROWS_WITH(parse_hands({"--hand", "sdh", "--hand", "allegro"}), "--hand: given twice");
  CHECK_THROWS_WITH(parse_hands({"--hand"}), "--hand: expected a value");
  CHECK(error_of({"--hand", "allegro"}) == "--hand: no hand \"allegro\" in this program (sdh)");
}

TEST_CASE("the option --hands lists several of the program's hands, in the order given",
          "[io][command_line]") {
  const std::vector<std::string_view> hands{"sdh", "allegro", "shadow"};
  const auto parse_hands = [&](std::initializer_list<std::string_view> args) {
    const std::vector<std::string_view> v(args);
    return parse_command_line(v, false, hands);
  };
  CHECK(parse_hands({}).hands.empty());
  CHECK(parse_hands({"--hands", "shadow,sdh"}).hands == std::vector<std::string>{"shadow", "sdh"});
  CHECK_THROWS_WITH(parse_hands({"--hands", "shadow,barrett"}),
                    "--hands: unknown hand \"barrett\" (expected sdh, allegro or shadow)");
  CHECK_THROWS_WITH(parse_hands({"--hands", "sdh,sdh"}),
                    "--hands: \"sdh\" is given twice in \"sdh,sdh\"");
  CHECK_THROWS_WITH(parse_hands({"--hands", "sdh,"}),
                    Catch::StartsWith("--hands: empty name in \"sdh,\""));
  CHECK_THROWS_WITH(parse_hands({"--hands", "sdh", "--hand", "allegro"}),
                    "--hands: not with --hand: give the hands in one list");
  CHECK_THROWS_WITH(parse_hands({"--hands", "sdh", "--hands", "allegro"}), "--hands: given twice");
}

TEST_CASE("the resume flag, and merge with the shards' folders", "[io][command_line]") {
  CHECK_FALSE(parse({}).resume);
  CHECK(parse({"--resume"}).resume);
  CHECK_FALSE(parse({}).merge);
  const CommandLine m = parse({"merge", "--out", "all", "s1", "--quiet", "s2", "--force"});
  CHECK(m.merge);
  CHECK(m.out == "all");
  CHECK(m.quiet);
  CHECK(m.force);
  CHECK(m.shards == std::vector<std::filesystem::path>{"s1", "s2"});
  CHECK(parse({"merge", "s1"}).out == "grasp_transfer_out");
  CHECK(parse({"merge", "--help"}).help);
  CHECK(error_of({"merge"}) == "merge: expected the shards' output folders");
  CHECK(error_of({"merge", "--out", "a"}) == "merge: expected the shards' output folders");
  CHECK_THAT(error_of({"merge", "--jobs", "2", "s1"}),
             Catch::StartsWith("--jobs: not an option of merge"));
  CHECK_THAT(error_of({"merge", "--resume", "s1"}),
             Catch::StartsWith("--resume: not an option of merge"));
  CHECK(error_of({"merge", "--out"}) == "--out: expected a value");
  CHECK(error_of({"merge", "--out", "--quiet", "s1"}) == "--out: expected a value");
  CHECK(error_of({"merge", "--out", "a", "--out", "b", "s1"}) == "--out: given twice");
  CHECK_THAT(error_of({"merge", "s1", ""}), Catch::StartsWith("merge: expected a shard's"));
  // "merge" anywhere but first is not the subcommand.
  CHECK_THAT(error_of({"--quiet", "merge"}), Catch::Contains("unknown option \"merge\""));
}

TEST_CASE("the option --human-grip sets the human hand's strongest grip", "[io][command_line]") {
  CHECK(parse({}).experiment.transfer.sim.human_max_grip == 5.0);
  CHECK(parse({"--human-grip", "1"}).experiment.transfer.sim.human_max_grip == 1.0);
  CHECK(parse({"--human-grip", "2.5"}).experiment.transfer.sim.human_max_grip == 2.5);
  for (const char* g : {"0.5", "0", "-1", "11", "nan", "inf", "x"}) {
    INFO(g);
    CHECK_THAT(error_of({"--human-grip", g}), Catch::StartsWith("--human-grip: "));
  }
  CHECK_THAT(error_of({"--human-grip", "0.5"}), Catch::Contains("in [1, 10]"));
}

TEST_CASE("an option's value is never empty nor another option", "[io][command_line][bad-input]") {
  CHECK_THAT(error_of({"--out", ""}), Catch::StartsWith("--out: expected a value"));
  CHECK_THAT(error_of({"--out", "--jobs", "2"}),
             Catch::StartsWith("--out: expected a value, got the option \"--jobs\""));
  CHECK_THAT(error_of({"--out"}), Catch::StartsWith("--out: expected a value"));
  for (const std::string_view option :
       {"--objects", "--methods", "--out", "--jobs", "--seed", "--shard", "--max-hypotheses",
        "--winding-reference", "--set", "--friction", "--hold-fraction", "--human-grip",
        "--judge"}) {
    INFO(option);
    CHECK_THAT(error_of({option, ""}),
               Catch::StartsWith(std::string(option) + ": expected a value"));
    CHECK_THAT(error_of({option, "--quiet"}),
               Catch::StartsWith(std::string(option) + ": expected a value, got the option"));
    CHECK_THAT(error_of({option}), Catch::StartsWith(std::string(option) + ": expected a value"));
  }
  CHECK_THAT(error_of({"--out", "a", "--out", "b"}), Catch::StartsWith("--out: given twice"));
  CHECK_THAT(error_of({"--out", std::string_view("a\0b", 3)}), Catch::Contains("NUL"));
  CHECK_THAT(error_of({"--outt", "x"}), Catch::Contains("unknown option \"--outt\""));
}

TEST_CASE("objects and methods are each given once", "[io][command_line][bad-input]") {
  CHECK(error_of({"--objects", "hammer,hammer"}) ==
        "--objects: \"hammer\" is given twice in \"hammer,hammer\"");
  CHECK(error_of({"--methods", "topological,topological"}) ==
        "--methods: \"topological\" is given twice in \"topological,topological\"");
  CHECK_THAT(error_of({"--objects", "hammer,,bottle"}), Catch::StartsWith("--objects: empty name"));
  CHECK_THAT(error_of({"--objects", "hammer,"}), Catch::StartsWith("--objects: empty name"));
  CHECK_THAT(error_of({"--objects", "anvil"}),
             Catch::StartsWith("--objects: unknown object \"anvil\"") && Catch::Contains("bottle"));
  CHECK_THAT(error_of({"--methods", "teleport"}),
             Catch::StartsWith("--methods: unknown method \"teleport\""));
  // A long list is refused at its first repeated name, without looking at the rest.
  std::string many = "hammer,bottle,mug,box,ball,can";
  while (many.size() < 3'000'000) many += ",x" + std::to_string(many.size());
  CHECK_THAT(error_of({"--objects", many}), Catch::StartsWith("--objects: unknown object \"x"));
  many = "topological,transplant,fingertip";
  while (many.size() < 3'000'000) many += ",fingertip";
  CHECK_THAT(error_of({"--methods", many}),
             Catch::StartsWith("--methods: \"fingertip\" is given twice in \"topological,") &&
                 Catch::EndsWith("...\""));
  CHECK_THAT(error_of({"--winding-reference", "palm"}),
             Catch::StartsWith("--winding-reference: unknown reference \"palm\""));
}

TEST_CASE("numbers are checked whole and in range", "[io][command_line][bad-input]") {
  CHECK_THAT(error_of({"--jobs", "zero"}), Catch::StartsWith("--jobs: expected a number"));
  CHECK_THAT(error_of({"--jobs", "2x"}), Catch::StartsWith("--jobs: expected a number"));
  CHECK_THAT(error_of({"--jobs", "0"}), Catch::StartsWith("--jobs: expected 1 to 1024"));
  CHECK_THAT(error_of({"--jobs", "1025"}), Catch::StartsWith("--jobs: expected 1 to 1024"));
  CHECK_THAT(error_of({"--jobs", "99999999999999"}), Catch::StartsWith("--jobs: number out of"));
  CHECK_THAT(error_of({"--seed", "-1"}), Catch::StartsWith("--seed: expected a number"));
  CHECK_THAT(error_of({"--seed", "18446744073709551616"}), Catch::StartsWith("--seed: number out"));
  CHECK_THAT(error_of({"--max-hypotheses", "-1"}), Catch::StartsWith("--max-hypotheses: expected"));
  for (const std::string_view mu : {"0", "-0.5", "10.5", "nan", "inf"}) {
    INFO(mu);
    CHECK_THAT(error_of({"--friction", mu}), Catch::StartsWith("--friction: "));
  }
  CHECK_THAT(error_of({"--friction", "0.5", "--friction", "0.3"}),
             Catch::StartsWith("--friction: given twice"));
  for (const std::string_view s : {"4/3", "0/3", "1/0", "3", "/", "1/", "a/b", "-1/2"}) {
    INFO(s);
    CHECK_THAT(error_of({"--shard", s}), Catch::StartsWith("--shard: expected"));
  }
}

TEST_CASE("every --set parameter is checked against its range before any work",
          "[io][command_line][bad-input]") {
  CHECK_THAT(error_of({"--set", "backoff=1e300"}),
             Catch::StartsWith("--set: backoff: must be in [0, 0.3]"));
  CHECK_THAT(error_of({"--set", "fingertip_scale=1e300"}),
             Catch::StartsWith("--set: fingertip_scale: must be in [0, 10]"));
  CHECK_THAT(error_of({"--set", "final_approach=-1"}),
             Catch::StartsWith("--set: final_approach: must be"));
  CHECK_THAT(error_of({"--set", "backoff=nan"}), Catch::Contains("backoff: must be in"));
  CHECK_THAT(error_of({"--set", "backoff=inf"}), Catch::Contains("backoff: must be in"));
  CHECK_THAT(error_of({"--set", "backoff=1e999"}),
             Catch::StartsWith("--set backoff: number out of range"));
  CHECK_THAT(error_of({"--set", "backoff=0.1cm"}),
             Catch::StartsWith("--set backoff: expected a number"));
  CHECK_THAT(error_of({"--set", "reach=1"}),
             Catch::StartsWith("--set: name: unknown transfer parameter \"reach\"") &&
                 Catch::Contains("final_approach"));
  CHECK_THAT(error_of({"--set", "final_approach"}),
             Catch::StartsWith("--set: expected NAME=VALUE"));
  CHECK_THAT(error_of({"--set", "=1"}), Catch::StartsWith("--set: expected NAME=VALUE"));
  CHECK_THAT(error_of({"--set", "backoff="}), Catch::StartsWith("--set: expected NAME=VALUE"));
  CHECK_THAT(error_of({"--set", "backoff=0.1", "--set", "backoff=0.2"}),
             Catch::StartsWith("--set: backoff is set twice"));
  // Every parameter: both ends of its range accepted, just outside refused.
  for (const TransferParameter& p : transfer_parameters) {
    INFO(p.name);
    const TransferOptions defaults;
    CHECK(p.get(defaults) >= p.min);
    CHECK(p.get(defaults) <= p.max);
    for (const double v : {p.min, p.max}) {
      TransferOptions o;
      set_transfer_parameter(o, p.name, v);
      CHECK(p.get(o) == v);
    }
    TransferOptions o;
    CHECK_THROWS_WITH(set_transfer_parameter(o, p.name, std::nextafter(p.max, 2 * p.max + 1)),
                      Catch::StartsWith(std::string(p.name) + ": must be in"));
    CHECK_THROWS_WITH(set_transfer_parameter(o, p.name, std::nextafter(p.min, -1.0)),
                      Catch::StartsWith(std::string(p.name) + ": must be in"));
    CHECK(p.get(o) == p.get(defaults));  // unchanged by the refused calls
    p.assign(o, p.max * 2 + 1);          // set directly, the run refuses it up front
    CHECK_THROWS_WITH(validate_transfer_parameters(o),
                      Catch::StartsWith(std::string(p.name) + ": must be in"));
  }
}

TEST_CASE("the option --judge picks the simulator; its default follows whether MuJoCo is linked",
          "[io][command_line]") {
  const auto parse_with = [](std::initializer_list<std::string_view> args, bool mujoco) {
    const std::vector<std::string_view> v(args);
    return parse_command_line(v, mujoco).experiment.judge;
  };
  CHECK(parse_with({}, false) == Judge::builtin);
  CHECK(parse_with({}, true) == Judge::both);
  CHECK(parse_with({"--judge", "builtin"}, true) == Judge::builtin);
  CHECK(parse_with({"--judge", "mujoco"}, true) == Judge::mujoco);
  CHECK(parse_with({"--judge", "both"}, true) == Judge::both);
  CHECK(parse_with({"--judge", "builtin"}, false) == Judge::builtin);
  CHECK(to_string(Judge::mujoco) == "mujoco");
}

TEST_CASE("the option --judge refuses an unknown engine, and MuJoCo where it is not linked",
          "[io][command_line][bad-input]") {
  CHECK(error_of({"--judge", "physx"}) ==
        "--judge: unknown judge \"physx\" (expected builtin, mujoco or both)");
  CHECK(error_of({"--judge", "builtin", "--judge", "builtin"}) == "--judge: given twice");
  for (const std::string_view j : {"mujoco", "both"}) {
    const std::string e = error_of({"--judge", j});  // parse() says MuJoCo is not linked
    INFO(e);
    CHECK(e.rfind("--judge: this grasp_transfer was built without MuJoCo", 0) == 0);
  }
  CHECK(error_of({"--judge"}) == "--judge: expected a value");
}

TEST_CASE("the usage lists every option and every parameter with its range", "[io][command_line]") {
  const std::string usage = command_line_usage();
  for (const char* option : {"--objects",    "--methods",        "--out",
                             "--force",      "--jobs",           "--seed",
                             "--shard",      "--max-hypotheses", "--winding-reference",
                             "--set",        "--friction",       "--hold-fraction",
                             "--human-grip", "--judge",          "--figures",
                             "--quiet",      "--help",           "--resume",
                             "merge",        "--every-test",     "exit status",
                             "results.json"}) {
    INFO(option);
    CHECK(usage.find(option) != std::string::npos);
  }
  for (const TransferParameter& p : transfer_parameters) {
    INFO(p.name);
    CHECK(usage.find(std::string(p.name) + " ") != std::string::npos);
    CHECK(usage.find(parameter_range(p)) != std::string::npos);
  }
}

TEST_CASE("no argument list makes the parser throw anything but invalid_argument",
          "[io][command_line][bad-input]") {
  // Random lists of tokens: options, values that are good for one option and bad for another,
  // and odd bytes. Each parse returns or throws topograsp::invalid_argument (anything else,
  // a crash or a hang fails the test).
  const std::vector<std::string_view> tokens = {"--objects",
                                                "--methods",
                                                "--out",
                                                "--jobs",
                                                "--seed",
                                                "--shard",
                                                "--max-hypotheses",
                                                "--winding-reference",
                                                "--set",
                                                "--judge",
                                                "mujoco",
                                                "--figures",
                                                "--quiet",
                                                "--force",
                                                "--resume",
                                                "merge",
                                                "--help",
                                                "-h",
                                                "",
                                                "--",
                                                "-",
                                                "hammer",
                                                "bottle,mug",
                                                "topological",
                                                "x",
                                                "1",
                                                "0",
                                                "-3",
                                                "1/2",
                                                "2/1",
                                                "99999999999999999999",
                                                "1e308",
                                                "nan",
                                                "backoff=0.1",
                                                "backoff=1e300",
                                                "a=b",
                                                "=",
                                                ",",
                                                "hammer,hammer",
                                                std::string_view("\0\xff", 2),
                                                "nearest_point",
                                                "/tmp/x",
                                                "1/0",
                                                "fingertip_scale=-0",
                                                "--set=1",
                                                "\n",
                                                "1/99999999999"};
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::size_t>(state >> 33);
  };
  int parsed = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<std::string_view> args(next() % 7);
    for (std::string_view& a : args) a = tokens[next() % tokens.size()];
    try {
      (void)parse_command_line(args);
      ++parsed;
    } catch (const topograsp::invalid_argument&) {
      ++refused;
    }
  }
  CHECK(parsed > 0);
  CHECK(refused > 0);
}
