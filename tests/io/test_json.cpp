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

TEST_CASE("json \\u escapes are parsed strictly and decoded to UTF-8", "[io][json][bad-input]") {
  using topograsp::invalid_argument;
  CHECK(Json::parse(R"("a\u0041b")").as_string() == "aAb");
  CHECK(Json::parse(R"("\u00e9")").as_string() == "\xC3\xA9");
  CHECK(Json::parse(R"("\u20AC")").as_string() == "\xE2\x82\xAC");
  CHECK(Json::parse(R"("\ud83d\ude00")").as_string() == "\xF0\x9F\x98\x80");
  CHECK(Json::parse(R"("\"\\\/\b\f\n\r\t")").as_string() == "\"\\/\b\f\n\r\t");
  // Used to throw std::invalid_argument("stoul"), and to accept "\u00zz" as "\0".
  CHECK_THROWS_AS(Json::parse(R"("\uZZZZ")"), invalid_argument);
  CHECK_THROWS_WITH(Json::parse(R"("\uZZZZ")"),
                    Catch::StartsWith("json") && Catch::Contains("offset 3"));
  CHECK_THROWS_WITH(Json::parse(R"("a\u00zzb")"), Catch::Contains("offset 6"));
  for (const char* bad : {R"("\u12")", R"("\u")", R"("\u-123")", R"("\u+123")", R"("\u 123")",
                          R"("\ud83d")", R"("\ud83dx")", R"("\ud83d\u0041")", R"("\ude00")",
                          R"("\x41")", R"("\)", "\"a\nb\"", "\"\x01\""}) {
    INFO(bad);
    CHECK_THROWS_AS(Json::parse(bad), invalid_argument);
  }
}

TEST_CASE("json numbers follow the grammar and the double range", "[io][json][bad-input]") {
  using topograsp::invalid_argument;
  CHECK(Json::parse("0").as_number() == 0.0);
  CHECK(Json::parse("-12.5e-1").as_number() == -1.25);
  CHECK(Json::parse("1E+2").as_number() == 100.0);
  CHECK(Json::parse("1.7976931348623157e308").as_number() == std::numeric_limits<double>::max());
  CHECK(Json::parse("5e-324").as_number() == std::numeric_limits<double>::denorm_min());
  CHECK(Json::parse("1e-400").as_number() == 0.0);
  CHECK(Json::parse("0.0000e99999999999999999999").as_number() == 0.0);
  CHECK(Json::parse("-1e-99999999999999999999").as_number() == 0.0);
  CHECK_THROWS_WITH(Json::parse("[1, 1e400]"),
                    Catch::Contains("out of the double range") && Catch::Contains("offset 4"));
  CHECK_THROWS_AS(Json::parse("-1e99999999999999999999"), invalid_argument);
  CHECK_THROWS_AS(Json::parse("100000000000000000000e300"), invalid_argument);
  for (const char* bad : {"01", "1.", ".5", "+1", "-", "1e", "1e+", "--1", "1.2.3", "0x10", "nan",
                          "inf", "-inf", "1e5e5", "- 1"}) {
    INFO(bad);
    CHECK_THROWS_AS(Json::parse(bad), invalid_argument);
  }
}

TEST_CASE("json nesting deeper than the limit is refused, not a stack overflow",
          "[io][json][bad-input]") {
  const auto nested = [](int depth) {
    return std::string(static_cast<std::size_t>(depth), '[') +
           std::string(static_cast<std::size_t>(depth), ']');
  };
  CHECK_NOTHROW(Json::parse(nested(Json::k_max_depth)));
  CHECK(Json::parse("[[[1]]]").as_array()[0].as_array()[0].as_array()[0].as_number() == 1.0);
  CHECK_THROWS_WITH(Json::parse(nested(Json::k_max_depth + 1)),
                    Catch::StartsWith("json") && Catch::Contains("nesting"));
  CHECK_THROWS_AS(Json::parse(nested(1000000)), topograsp::invalid_argument);
  CHECK_THROWS_AS(Json::parse(std::string(1000000, '{')), topograsp::invalid_argument);
}

TEST_CASE("every json parse error is a topograsp::invalid_argument", "[io][json][bad-input]") {
  // Every prefix of a valid document is either valid or refused with the documented exception.
  const std::string text =
      R"({"a": [1, -2.5e-3, true, false, null, "x\u00e9\ud83d\ude00\n"], "b": {"c": 0}})";
  REQUIRE_NOTHROW(Json::parse(text));
  for (std::size_t n = 0; n < text.size(); ++n) {
    const std::string prefix = text.substr(0, n);
    INFO(prefix);
    try {
      (void)Json::parse(prefix);
    } catch (const topograsp::invalid_argument&) {
    }
  }
}

TEST_CASE("Json numbers survive a dump and a parse bit for bit", "[io][json]") {
  // Found by the JSON fuzzer: dump() wrote 10 significant digits.
  for (const double d : {7.11131131111, 0.1, 1.0 / 3.0, 12345678901234567890.0, -2.5e-308,
                         1.7976931348623157e308, 4.9e-324, 0.8378378378378378, 1e15, -1e14}) {
    Json list = Json::array();
    list.push_back(d);
    const Json back = Json::parse(list.dump(0));
    CHECK(back.as_array()[0].as_number() == d);
  }
  Json small = Json::array();
  small.push_back(0.5312).push_back(101);
  CHECK(small.dump(0) == "[0.5312,101]");
}
