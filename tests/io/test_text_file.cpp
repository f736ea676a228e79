// SPDX-License-Identifier: BSD-3-Clause
// The number formatting and XML escaping that every SVG and HTML writer shares.
#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <topograsp/io/text_file.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>

#include "support/text.hpp"

using namespace topograsp;
using test::count;

TEST_CASE("svg numbers have fixed decimals and never a negative zero", "[io][text_file]") {
  CHECK(detail::svg_number(1.005) == "1.00");  // 1.005 is 1.00499... in binary
  CHECK(detail::svg_number(-2.5) == "-2.50");
  CHECK(detail::svg_number(12.345, 1) == "12.3");
  CHECK(detail::svg_number(-7.6, 0) == "-8");
  CHECK(detail::svg_number(0.0) == "0.00");
  CHECK(detail::svg_number(-0.0) == "0.00");
  CHECK(detail::svg_number(-0.001) == "0.00");
  CHECK(detail::svg_number(-1e-300) == "0.00");
  CHECK(detail::svg_number(-0.004, 2) == "0.00");
  CHECK(detail::svg_number(-0.4, 0) == "0");
  CHECK(detail::svg_number(-0.0, 0) == "0");
  CHECK(detail::svg_number(-0.00049, 3) == "0.000");
  CHECK(detail::svg_number(-0.0005, 3) == "-0.001");  // -0.0005 is -0.000500000...01 in binary
  CHECK(detail::svg_number(-1e300, 2).size() > 300);  // no truncation of huge values
}

TEST_CASE("xml_escape escapes all five XML special characters", "[io][text_file]") {
  CHECK(detail::xml_escape("a<b>&\"c'd") == "a&lt;b&gt;&amp;&quot;c&#39;d");
  CHECK(detail::xml_escape("plain \xCE\xB3 text") == "plain \xCE\xB3 text");
  CHECK(detail::xml_escape("") == "");
}

TEST_CASE("the line plot escapes every label and prints no negative zero", "[io][svg_plot]") {
  SvgLinePlot plot("it's <a & b>", "x \"in\" m", "y's");
  plot.add_series("O'Brien & co", {0.0, 1.0, 2.0}, {-0.004, 0.0, 0.004});
  plot.add_reference("<ref>", -0.002);
  const std::string svg = plot.str();
  CHECK(count(svg, ">it&#39;s &lt;a &amp; b&gt;</text>") == 1);
  CHECK(count(svg, ">x &quot;in&quot; m</text>") == 1);
  CHECK(count(svg, ">y&#39;s</text>") == 1);
  CHECK(count(svg, ">O&#39;Brien &amp; co</text>") == 1);
  CHECK(count(svg, ">&lt;ref&gt;</text>") == 1);
  CHECK(count(svg, "'") == 0);  // attributes are double-quoted, so ' appears only escaped
  // No number that reads as a negative zero ("-0", "-0.00", ...); "-0.004" is fine.
  const std::regex negative_zero("-0(\\.0*)?(?![.0-9])");
  CHECK_FALSE(std::regex_search(svg, negative_zero));
  CHECK(count(svg, ">-0.004</text>") == 1);  // the lowest y tick
  CHECK(count(svg, ">0.000</text>") == 1);   // the y tick at zero, signless
}
