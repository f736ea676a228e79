// SPDX-License-Identifier: BSD-3-Clause
// Parameter tables (core/parameters.hpp): ranges, checks, setting by name, the --help rows; and
// the library's tables (every default inside its range).
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/aico/options.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/grasp/transfer/options.hpp>
#include <topograsp/physics/stepper_options.hpp>

using namespace topograsp;

namespace {

struct Knobs {
  double gain = 0.5;
  int count = 3;
  double slack = 1.0;
};

constexpr ParameterTable<Knobs, 3> knob_parameters{{
    {"gain", &Knobs::gain, 0.0, 1.0, "the gain", true},
    {"count", &Knobs::count, 1, 10, "how many"},
    {"slack", &Knobs::slack, 0.0, unbounded, "m: the slack"},
}};

// Every default of table inside its range, and each end of a bounded range accepted by
// set_parameter with its neighbour outside refused.
template <class Options, std::size_t N>
void check_table(const ParameterTable<Options, N>& table) {
  const Options defaults{};
  for (const Parameter<Options>& p : table) {
    INFO(p.name);
    CHECK_NOTHROW(check_parameter(p, p.get(defaults)));
    CHECK(find_parameter(table, p.name) == &p);
    Options o{};
    const double below = p.integer() ? p.min - 1 : std::nextafter(p.min, -unbounded);
    CHECK_THROWS_WITH(set_parameter(o, table, p.name, below),
                      Catch::StartsWith(std::string(p.name) + ": must be in "));
    if (!p.above_min) {
      set_parameter(o, table, p.name, p.min);
      CHECK(p.get(o) == p.min);
    }
    if (!std::isinf(p.max)) {
      set_parameter(o, table, p.name, p.max);
      CHECK(p.get(o) == p.max);
      const double above = p.integer() ? p.max + 1 : std::nextafter(p.max, unbounded);
      CHECK_THROWS_WITH(set_parameter(o, table, p.name, above),
                        Catch::StartsWith(std::string(p.name) + ": must be in "));
    }
  }
}

}  // namespace

TEST_CASE("a parameter's range prints as an interval", "[core][parameters]") {
  CHECK(parameter_range(knob_parameters[0]) == "(0, 1]");
  CHECK(parameter_range(knob_parameters[1]) == "[1, 10]");
  CHECK(parameter_range(knob_parameters[2]) == "[0, inf)");
  CHECK(knob_parameters[1].integer());
  CHECK_FALSE(knob_parameters[0].integer());
}

TEST_CASE("validate_parameters names the first field outside its range", "[core][parameters]") {
  Knobs k;
  CHECK_NOTHROW(validate_parameters(k, knob_parameters, "options."));
  k.gain = 0.0;  // the range excludes 0
  k.count = 11;
  CHECK_THROWS_WITH(validate_parameters(k, knob_parameters, "options."),
                    "options.gain: must be in (0, 1] (the gain), got 0");
  k.gain = 1.0;
  CHECK_THROWS_WITH(validate_parameters(k, knob_parameters, "options."),
                    "options.count: must be in [1, 10], a whole number (how many), got 11");
  k.count = 10;
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), unbounded, -1e-300}) {
    k.slack = bad;
    CHECK_THROWS_WITH(validate_parameters(k, knob_parameters),
                      Catch::StartsWith("slack: must be in [0, inf) (m: the slack), got "));
  }
  k.slack = 1e300;  // finite: inside an unbounded range
  CHECK_NOTHROW(validate_parameters(k, knob_parameters));
}

TEST_CASE("set_parameter sets a field by name or leaves the options as they were",
          "[core][parameters][bad-input]") {
  Knobs k;
  set_parameter(k, knob_parameters, "count", 7.0);
  CHECK(k.count == 7);
  set_parameter(k, knob_parameters, "gain", 0.25);
  CHECK(k.gain == 0.25);
  CHECK_THROWS_WITH(set_parameter(k, knob_parameters, "count", 2.5),
                    "count: must be in [1, 10], a whole number (how many), got 2.5");
  CHECK_THROWS_WITH(set_parameter(k, knob_parameters, "gian", 0.1, "knob"),
                    "name: unknown knob \"gian\" (expected one of gain, count, slack)");
  CHECK(k.count == 7);
  CHECK(k.gain == 0.25);
  CHECK(find_parameter(knob_parameters, "gian") == nullptr);
}

TEST_CASE("parameter_help lists name, default, range and meaning", "[core][parameters]") {
  const std::string help = parameter_help(knob_parameters, Knobs{});
  CHECK_THAT(help, Catch::StartsWith("  name "));
  CHECK_THAT(help, Catch::Contains("  gain                     0.5       (0, 1]       the gain\n"));
  CHECK_THAT(help, Catch::Contains("  count                    3         [1, 10]      how many\n"));
}

TEST_CASE("the library's parameter tables hold their defaults and both ends of their ranges",
          "[core][parameters]") {
  check_table(transfer_parameters);
  check_table(aico_parameters);
  check_table(close_parameters);
  check_table(stability_parameters);
  check_table(stepper_parameters);
}

TEST_CASE("the documentation's example of a parameter table", "[core][parameters]") {
  AicoOptions o;
  set_parameter(o, aico_parameters, "max_sweeps", 200);
  CHECK(o.max_sweeps == 200);
  o.tolerance = -1.0;
  CHECK_THROWS_WITH(validate_parameters(o, aico_parameters, "options."),
                    "options.tolerance: must be in (0, inf) (rad: step tolerance), got -1");
}
