// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <string>
#include <topograsp/io/json.hpp>
#include <topograsp/io/json_position.hpp>

using namespace topograsp;

TEST_CASE("json_field_line: the line where a field is written", "[io][json]") {
  const std::string text = R"({
  "name": "gripper",
  "note": "a \"quoted\" {brace} [and] a \u0041 escape",
  "fingers": [
    {"name": "index", "points": ["a", "b"]},
    {
      "name": "middle",
      "points": [
        "c",
        "d"
      ]
    }
  ],
  "joints": {"wrist.roll": {"hold": 0.1},
             "slide": {
               "hold": -2.5e-3, "ok": true, "none": null}},
  "empty": []
})";
  REQUIRE_NOTHROW(Json::parse(text));  // the scanner trusts its text to be JSON
  CHECK(json_field_line(text, "") == 1);
  CHECK(json_field_line(text, "name") == 2);
  CHECK(json_field_line(text, "fingers") == 4);
  CHECK(json_field_line(text, "fingers[0]") == 5);
  CHECK(json_field_line(text, "fingers[0].points[1]") == 5);
  CHECK(json_field_line(text, "fingers[1]") == 6);
  CHECK(json_field_line(text, "fingers[1].name") == 7);
  CHECK(json_field_line(text, "fingers[1].points") == 8);
  CHECK(json_field_line(text, "fingers[1].points[1]") == 10);
  CHECK(json_field_line(text, "joints.wrist.roll.hold") == 14);  // a key with a dot
  CHECK(json_field_line(text, "joints.slide") == 15);
  CHECK(json_field_line(text, "joints.slide.none") == 16);
  // Not all in the text: the line of its deepest part that is.
  CHECK(json_field_line(text, "thumb") == 1);
  CHECK(json_field_line(text, "fingers[2]") == 4);
  CHECK(json_field_line(text, "fingers[1].points[5]") == 8);
  CHECK(json_field_line(text, "joints.elbow.hold") == 14);
  CHECK(json_field_line(text, "name.first") == 2);  // a string holds no member
  CHECK(json_field_line(text, "empty[0]") == 17);
  CHECK(json_field_line(text, "fingers[x]") == 4);  // not an index
  CHECK(json_field_line(text, "fingers[") == 4);
  // Text that is not JSON: where the scan stopped, never past the text.
  CHECK(json_field_line("", "a") == 1);
  CHECK(json_field_line("{\n\"a\": [1,", "a[3]") == 2);
  CHECK(json_field_line("{\"a\": \"unterminated", "b") == 1);
}
