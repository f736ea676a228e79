// SPDX-License-Identifier: BSD-3-Clause
#include <stdlib.h>  // mkdtemp

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <catch2/catch.hpp>

#include <topograsp/io/xml.hpp>

using namespace topograsp;

namespace {

// The xml_error that parse_xml(text, "hand.urdf") throws, after checking that it is one, with the
// line \p line and a message "hand.urdf:<line>: ..." that contains \p fragment.
void check_xml_error(std::string_view text, int line, const std::string& fragment) {
  INFO("text: " << text);
  try {
    (void)parse_xml(text, "hand.urdf");
  } catch (const xml_error& e) {
    INFO("what(): " << e.what());
    CHECK(e.file() == "hand.urdf");
    CHECK(e.line() == line);
    const std::string what = e.what();
    CHECK(what.rfind("hand.urdf:" + std::to_string(line) + ": ", 0) == 0);
    CHECK(what.find(fragment) != std::string::npos);
    CHECK(e.problem().find(fragment) != std::string::npos);
    return;
  }
  FAIL("no xml_error");
}

// \p n nested elements <e>, one start tag per line, then their end tags.
std::string xml_nested(int n) {
  std::string s;
  for (int k = 0; k < n; ++k) s += "<e>\n";
  for (int k = 0; k < n; ++k) s += "</e>";
  return s;
}

// A scratch folder, removed with its contents.
struct XmlTempDir {
  std::filesystem::path path;
  XmlTempDir() {
    std::string templ = (std::filesystem::temp_directory_path() / "topograsp-xml-XXXXXX").string();
    REQUIRE(::mkdtemp(templ.data()) != nullptr);
    path = templ;
  }
  ~XmlTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  XmlTempDir(const XmlTempDir&) = delete;
  XmlTempDir& operator=(const XmlTempDir&) = delete;
};

constexpr std::string_view k_urdf = R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- a two-link finger -->
<robot name="finger">
  <link name="base">
    <visual>
      <origin xyz="0 0 0.1" rpy="0 0 0"/>
      <geometry><box size="0.1 0.1 0.2"/></geometry>
    </visual>
  </link>
  <joint name="knuckle" type="revolute">
    <parent link="base"/>
    <child link="tip"/>
    <axis xyz = '0 1 0' />
    <limit lower="-0.5" upper="1.57" effort="10" velocity="2"/>
  </joint>
  <link name="tip"/>
</robot>
)";

}  // namespace

TEST_CASE("xml reads a URDF-like document with nested elements and attributes", "[io][xml]") {
  const XmlDocument doc = parse_xml(k_urdf, "finger.urdf");
  CHECK(doc.file == "finger.urdf");
  const XmlElement& robot = doc.root;
  CHECK(robot.name == "robot");
  CHECK(robot.line == 3);
  REQUIRE(robot.attributes.size() == 1);
  CHECK(robot.attributes[0].name == "name");
  CHECK(robot.attributes[0].value == "finger");
  REQUIRE(robot.children.size() == 3);

  const XmlElement& base = robot.children[0];
  CHECK(base.name == "link");
  CHECK(base.line == 4);
  REQUIRE(base.attribute("name") != nullptr);
  CHECK(*base.attribute("name") == "base");
  CHECK(base.has("name"));
  CHECK_FALSE(base.has("type"));
  CHECK(base.attribute("type") == nullptr);
  REQUIRE(base.children.size() == 1);
  const XmlElement& visual = base.children[0];
  REQUIRE(visual.children.size() == 2);
  CHECK(visual.children[0].name == "origin");
  CHECK(visual.children[0].line == 6);
  CHECK(*visual.children[0].attribute("xyz") == "0 0 0.1");
  CHECK(visual.children[0].children.empty());
  const XmlElement& geometry = visual.children[1];
  CHECK(geometry.line == 7);
  REQUIRE(geometry.children.size() == 1);
  CHECK(geometry.children[0].name == "box");
  CHECK(geometry.children[0].line == 7);
  CHECK(*geometry.children[0].attribute("size") == "0.1 0.1 0.2");

  const XmlElement& joint = robot.children[1];
  CHECK(joint.name == "joint");
  CHECK(joint.line == 10);
  REQUIRE(joint.attributes.size() == 2);  // in document order
  CHECK(joint.attributes[0].name == "name");
  CHECK(joint.attributes[1].name == "type");
  CHECK(joint.attributes[1].value == "revolute");
  REQUIRE(joint.children.size() == 4);
  CHECK(joint.children[2].name == "axis");
  CHECK(joint.children[2].line == 13);
  CHECK(*joint.children[2].attribute("xyz") == "0 1 0");  // single quotes, spaces around '='
  const XmlElement& limit = joint.children[3];
  CHECK(limit.attributes.size() == 4);
  CHECK(*limit.attribute("lower") == "-0.5");
  CHECK(*limit.attribute("velocity") == "2");

  CHECK(robot.children[2].name == "link");
  CHECK(robot.children[2].line == 16);
  // The text of an element is all its character data, whitespace between children included.
  CHECK(base.text == "\n    \n  ");
  CHECK(geometry.text.empty());
}

TEST_CASE("xml skips comments, processing instructions and a DOCTYPE", "[io][xml]") {
  const XmlDocument doc = parse_xml(
      "\xEF\xBB\xBF<?xml version='1.0'?>\n"
      "<!DOCTYPE mujoco [\n"
      "  <!ENTITY e \"]>\">  <!-- a ] and a > -->\n"
      "  <?pi ]> ?>\n"
      "]>\n"
      "<!-- before -- the root -->\n"
      "<mujoco model='hand'><!-- inside --><?mark?><default class=\"main\"/>"
      "<!---->x</mujoco>\n"
      "<!-- after -->\n<?after?>\n  \n",
      "hand.xml");
  CHECK(doc.root.name == "mujoco");
  CHECK(doc.root.line == 7);
  CHECK(*doc.root.attribute("model") == "hand");
  REQUIRE(doc.root.children.size() == 1);
  CHECK(doc.root.children[0].name == "default");
  CHECK(*doc.root.children[0].attribute("class") == "main");
  CHECK(doc.root.text == "x");
  // A DOCTYPE without an internal subset.
  CHECK(parse_xml("<!DOCTYPE robot SYSTEM \"robot.dtd\"><robot/>", "f").root.name == "robot");
}

TEST_CASE("xml decodes entities, character references and CDATA", "[io][xml]") {
  const XmlDocument doc = parse_xml(
      "<a v=\"&lt;&gt;&amp;&apos;&quot; &#65;&#x42;&#x63;\" w='\"' x=\"'\">"
      "1 &lt; 2 &amp;&amp; 3 &gt; 2<![CDATA[ <b>&amp;</b> ]] ]]>&#x20AC;&#8364;&#x1F600;&#xe9;"
      "</a>",
      "f.xml");
  CHECK(*doc.root.attribute("v") == "<>&'\" ABc");
  CHECK(*doc.root.attribute("w") == "\"");
  CHECK(*doc.root.attribute("x") == "'");
  CHECK(doc.root.children.empty());  // CDATA is text, not markup
  CHECK(doc.root.text ==
        "1 < 2 && 3 > 2 <b>&amp;</b> ]] \xE2\x82\xAC\xE2\x82\xAC\xF0\x9F\x98\x80\xC3\xA9");
  // An element name with the allowed characters, namespace prefix included.
  const XmlDocument names = parse_xml("<x:a-b.c_1 _d.e-f:g='1'/>", "f.xml");
  CHECK(names.root.name == "x:a-b.c_1");
  CHECK(*names.root.attribute("_d.e-f:g") == "1");
}

TEST_CASE("xml normalises line ends and counts lines at \\n, \\r\\n and \\r", "[io][xml]") {
  const XmlDocument doc = parse_xml(
      "<a\r\n v='1\r\n2\t3\n4&#10;5'>x\r\ny\rz<![CDATA[\r\n]]>\r\n<b/>\r<c/>\n<d/></a>", "f.xml");
  CHECK(*doc.root.attribute("v") == "1 2 3 4\n5");  // literal line ends and tabs become spaces
  CHECK(doc.root.text == "x\ny\nz\n\n\n\n");
  REQUIRE(doc.root.children.size() == 3);
  // Line ends: \r\n, \r\n, \n, \r\n, \r (a lone one), \r\n, \r\n, then <b/>; \r, <c/>; \n, <d/>.
  CHECK(doc.root.children[0].line == 8);
  CHECK(doc.root.children[1].line == 9);
  CHECK(doc.root.children[2].line == 10);
  check_xml_error("<a>\r\n\r\n<b></c></a>", 3, "does not match");
}

TEST_CASE("xml reports unexpected end of input at the last line", "[io][xml][bad-input]") {
  check_xml_error("<robot>\n  <link name='a'>\n", 2, "unexpected end of input");
  check_xml_error("<robot>\n  <link name='a'>\n", 2, "<link> (line 2) is not closed");
  check_xml_error("<robot>\n<link name='a", 2, "unexpected end of input");
  check_xml_error("<robot>\n<link name='a'", 2, "in the start tag <link>");
  check_xml_error("<robot>\n<link\n", 2, "unexpected end of input");
  check_xml_error("<robot></robot", 1, "unexpected end of input");
  check_xml_error("<robot>\n<!-- open\n\n", 3, "the comment at line 2 is not closed");
  check_xml_error("<robot><![CDATA[ x ]]", 1, "the CDATA section at line 1 is not closed");
  check_xml_error("<?xml version='1.0'", 1, "the processing instruction at line 1");
  check_xml_error("<!DOCTYPE robot [\n<!ENTITY a 'b'>\n", 2, "the <!DOCTYPE> at line 1");
  check_xml_error("<robot>&amp", 1, "unexpected end of input");
  check_xml_error("<robot>&#12", 1, "unexpected end of input");
  check_xml_error("<", 1, "unexpected end of input");
}

TEST_CASE("xml refuses an end tag that does not match its start tag", "[io][xml][bad-input]") {
  check_xml_error("<robot>\n  <joint name='j'>\n  </link>\n</robot>", 3,
                  "end tag </link> does not match the start tag <joint> at line 2");
  check_xml_error("<robot></robot></robot>", 1, "end tag </robot> without a start tag");
  check_xml_error("<robot>\n</robot x>", 2, "expected '>' to close </robot>");
}

TEST_CASE("xml refuses malformed start tags and attributes", "[io][xml][bad-input]") {
  check_xml_error("<robot>\n<joint name='a' name=\"b\"/>\n</robot>", 2,
                  "duplicate attribute 'name' in <joint>");
  std::string many = "<a";
  for (int k = 0; k < 40; ++k) many += " n" + std::to_string(k) + "='1'";
  CHECK(parse_xml(many + "/>", "f").root.attributes.size() == 40);
  check_xml_error(many + "\n n25='2'/>", 2, "duplicate attribute 'n25' in <a>");  // the hash set
  check_xml_error("<robot>\n<joint name=a/>\n</robot>", 2,
                  "expected a value in quotes (' or \") for attribute 'name' in <joint>");
  check_xml_error("<robot>\n<joint name/>", 2, "expected '=' after attribute 'name' in <joint>");
  check_xml_error("<robot>\n<joint name='a<b'/>", 2, "'<' in the value of attribute 'name'");
  check_xml_error("<robot>\n\n<joint name='a' <link/>", 3, "expected '>' to close <joint>");
  check_xml_error("<robot><joint name='a'type='b'/>", 1,
                  "expected whitespace before attribute 'type' in <joint>");
  check_xml_error("<robot>\n< joint/>", 2, "expected an element name after '<'");
  check_xml_error("<1robot/>", 1, "expected an element name after '<'");
  check_xml_error("<robot/ >", 1, "expected '>' to close <robot>");
}

TEST_CASE("xml refuses bad references", "[io][xml][bad-input]") {
  check_xml_error("<robot>\n&nbsp;</robot>", 2, "unknown entity &nbsp;");
  check_xml_error("<robot>\n<a v='&nbsp;'/></robot>", 2, "unknown entity &nbsp;");
  check_xml_error("<robot>a & b</robot>", 1, "'&' that does not start an entity reference");
  check_xml_error("<robot>&amp</robot>", 1, "'&' that does not start an entity reference");
  check_xml_error("<robot>&#0;</robot>", 1, "character reference &#0; is not a valid character");
  check_xml_error("<robot>&#xD800;</robot>", 1, "&#xD800; is not a valid character");
  check_xml_error("<robot>&#x110000;</robot>", 1, "&#x110000; is not a valid character");
  check_xml_error("<robot>&#99999999999999999999;</robot>", 1, "is not a valid character");
  check_xml_error("<robot>&#;</robot>", 1, "bad character reference");
  check_xml_error("<robot>&#x;</robot>", 1, "bad character reference");
  check_xml_error("<robot>&#X41;</robot>", 1, "bad character reference");
  check_xml_error("<robot>&#12a;</robot>", 1, "bad character reference");
  CHECK(parse_xml("<r>&#x10FFFF;&#xD7FF;&#xE000;</r>", "f").root.text ==
        "\xF4\x8F\xBF\xBF\xED\x9F\xBF\xEE\x80\x80");
}

TEST_CASE("xml allows only whitespace, comments and PIs around the root", "[io][xml][bad-input]") {
  check_xml_error("<robot/>\n\nx", 3, "text after the root element <robot>");
  check_xml_error("<robot></robot>\n<robot/>", 2, "element <robot> after the root element <robot>");
  check_xml_error("x<robot/>", 1, "text before the root element");
  check_xml_error("<robot/><![CDATA[x]]>", 1, "CDATA section outside the root element");
  check_xml_error("<robot/>\n<!DOCTYPE robot>", 2, "<!DOCTYPE> after the root element");
  check_xml_error("<!DOCTYPE a><!DOCTYPE a><a/>", 1, "a second <!DOCTYPE>");
  check_xml_error("<robot><!DOCTYPE a></robot>", 1, "<!DOCTYPE> inside an element");
  check_xml_error("<robot><!ELEMENT a></robot>", 1, "unknown markup");
  check_xml_error("<robot>]]></robot>", 1, "']]>' in text");
  check_xml_error("<robot>\n\x01</robot>", 2, "control character 0x01");
  check_xml_error(std::string_view("<robot>\0</robot>", 16), 1, "control character 0x00");
  check_xml_error("\xFF\xFE<\0r\0/\0>\0", 1, "UTF-16 is not supported");
  CHECK(parse_xml("\n \t\r\n<robot/>\n\n", "f").root.line == 3);
}

TEST_CASE("xml refuses a document without a root element", "[io][xml][bad-input]") {
  check_xml_error("", 1, "no root element");
  check_xml_error("\xEF\xBB\xBF", 1, "no root element");
  check_xml_error("<?xml version='1.0'?>\n<!-- only a comment -->\n", 2, "no root element");
}

TEST_CASE("xml accepts 256 nested elements and refuses 257", "[io][xml][bad-input]") {
  const XmlDocument doc = parse_xml(xml_nested(k_xml_max_depth), "deep.xml");
  const XmlElement* e = &doc.root;
  int depth = 1;
  while (!e->children.empty()) {
    e = &e->children[0];
    ++depth;
  }
  CHECK(depth == 256);
  CHECK(e->line == 256);
  check_xml_error(xml_nested(257), 257, "elements nested deeper than 256 levels");
  // Far deeper hostile input is refused the same way, without exhausting the stack.
  std::string hostile;
  for (int k = 0; k < 200000; ++k) hostile += "<a>";
  check_xml_error(hostile, 1, "elements nested deeper than 256 levels");
}

TEST_CASE("xml parses large documents", "[io][xml]") {
  std::string text = "<mujoco>\n";
  for (int k = 0; k < 20000; ++k) text += "<geom name='g" + std::to_string(k) + "' size='1'/>\n";
  text += "<body";
  for (int k = 0; k < 20000; ++k) text += " a" + std::to_string(k) + "='&lt;'";
  text += ">" + std::string(100000, 'x') + "</body></mujoco>";
  const XmlDocument doc = parse_xml(text, "big.xml");
  REQUIRE(doc.root.children.size() == 20001);
  CHECK(doc.root.children[19999].line == 20001);
  CHECK(doc.root.children[20000].attributes.size() == 20000);
  CHECK(doc.root.children[20000].text.size() == 100000);
}

TEST_CASE("read_xml_file reads a file and names the path in errors", "[io][xml][bad-input]") {
  const XmlTempDir dir;
  const std::string path = (dir.path / "hand.urdf").string();
  {
    std::ofstream f(path, std::ios::binary);
    f << "<robot name='hand'>\n  <link name='palm'>\n</robot>\n";
  }
  try {
    (void)read_xml_file(path);
    FAIL("no xml_error");
  } catch (const xml_error& e) {
    CHECK(e.file() == path);
    CHECK(e.line() == 3);
    CHECK(std::string(e.what()) ==
          path + ":3: end tag </robot> does not match the start tag <link> at line 2");
  }
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << "<robot name='hand'><link name='palm'/></robot>\n";
  }
  const XmlDocument doc = read_xml_file(path);
  CHECK(doc.file == path);
  CHECK(doc.root.children.at(0).name == "link");

  const std::string missing = (dir.path / "missing.urdf").string();
  try {
    (void)read_xml_file(missing);
    FAIL("no xml_error");
  } catch (const xml_error& e) {
    CHECK(e.file() == missing);
    CHECK(e.line() == 0);
    CHECK(std::string(e.what()) == missing + ": cannot be opened");
  }
  CHECK_THROWS_WITH(read_xml_file(dir.path.string()), Catch::Contains("cannot be opened"));
  // xml_error is the library's invalid-argument error.
  CHECK_THROWS_AS(parse_xml("", "f"), topograsp::invalid_argument);
}
