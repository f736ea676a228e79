// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <limits>
#include <topograsp/io/json.hpp>

using namespace topograsp;

TEST_CASE("json values round-trip through text", "[io][json]") {
  Json doc = Json::object();
  doc.set("name", "hammer \"claw\"\n");
  doc.set("count", 101);
  doc.set("rate", 0.5312);
  doc.set("ok", true);
  doc.set("none", nullptr);
  Json list = Json::array();
  list.push_back(1.5).push_back(-2).push_back(Json::object());
  doc.set("list", list);
  for (const int indent : {0, 2}) {
    const Json back = Json::parse(doc.dump(indent));
    CHECK(back.at("name").as_string() == "hammer \"claw\"\n");
    CHECK(back.at("count").as_number() == 101);
    CHECK(back.at("rate").as_number() == Approx(0.5312));
    CHECK(back.at("ok").as_bool());
    CHECK(back.at("none").is_null());
    CHECK(back.at("list").as_array().size() == 3);
    CHECK(back.at("list").as_array()[2].is_object());
  }
  CHECK(doc.dump(0) ==
        R"({"name":"hammer \"claw\"\n","count":101,"rate":0.5312,"ok":true,"none":null,)"
        R"("list":[1.5,-2,{}]})");
}

TEST_CASE("json writes non-finite numbers as null", "[io][json]") {
  Json a = Json::array();
  a.push_back(std::numeric_limits<double>::quiet_NaN());
  a.push_back(std::numeric_limits<double>::infinity());
  CHECK(a.dump(0) == "[null,null]");
}

TEST_CASE("malformed json is rejected with the offset", "[io][json][bad-input]") {
  for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "tru", "\"open", "1 2", "{\"a\":-}"}) {
    INFO(bad);
    CHECK_THROWS_AS(Json::parse(bad), topograsp::invalid_argument);
  }
  CHECK_THROWS_WITH(Json::parse("[1,]"), Catch::Contains("json") && Catch::Contains("offset"));
  CHECK_THROWS_AS(Json::parse("[1]").at("x"), std::logic_error);
}
