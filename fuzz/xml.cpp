// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: parse_xml (io/xml.hpp) on any bytes.
//
// - Only topograsp::xml_error may escape parse_xml() (its documented error); anything else
//   (std::out_of_range, std::length_error, ...) is a failure. The error names the file given and
//   a line of the text ("FILE:LINE: problem", 1 <= LINE <= the number of lines).
// - A document that parses is well-formed as the header says: at most k_xml_max_depth levels,
//   names made of the allowed characters, distinct attribute names per element, element lines
//   in [1, number of lines] and not decreasing in document order.
// - Written back as XML (text escaped, attribute values quoted and escaped) it parses again to
//   the same tree: same names, attributes in the same order with the same values, same text byte
//   for byte, same children.

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>
#include <unordered_set>

#include <topograsp/io/xml.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::XmlDocument;
using topograsp::XmlElement;
using topograsp::fuzz::c_literal;
using topograsp::fuzz::fuzz_fail;

constexpr std::string_view k_file = "fuzz.xml";

// The number of lines of \p t as parse_xml counts them (line ends "\n", "\r\n" and a lone '\r').
int line_count(std::string_view t) {
  int lines = 1;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] == '\n' || (t[i] == '\r' && (i + 1 >= t.size() || t[i + 1] != '\n'))) ++lines;
  return lines;
}

bool is_name(std::string_view n) {
  const auto start = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
           static_cast<unsigned char>(c) >= 0x80;
  };
  if (n.empty() || !start(n[0])) return false;
  for (const char c : n)
    if (!start(c) && !(c >= '0' && c <= '9') && c != '-' && c != '.') return false;
  return true;
}

void append_escaped(std::string& out, std::string_view s, bool attribute) {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '&') {
      out += "&amp;";
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else if (attribute && c == '"') {
      out += "&quot;";
    } else if (u < 0x20 && (attribute || (c != '\t' && c != '\n'))) {
      out += "&#" + std::to_string(u) + ";";
    } else {
      out += c;
    }
  }
}

// \p e written as XML (its text before its children: the text is one concatenation anyway).
// Recursion is bounded by the parser's depth limit.
void write(std::string& out, const XmlElement& e) {
  out += '<';
  out += e.name;
  for (const auto& a : e.attributes) {
    out += ' ';
    out += a.name;
    out += "=\"";
    append_escaped(out, a.value, true);
    out += '"';
  }
  out += '>';
  append_escaped(out, e.text, false);
  for (const XmlElement& c : e.children) write(out, c);
  out += "</";
  out += e.name;
  out += '>';
}

// What is wrong in the parsed tree \p e at depth \p depth ("" if nothing); \p last_line is the
// line of the element before it in document order.
std::string check_tree(const XmlElement& e, int depth, int lines, int& last_line,
                       const std::string& path) {
  const std::string here = path + "/" + e.name;
  if (depth > topograsp::k_xml_max_depth) return here + ": deeper than k_xml_max_depth";
  if (!is_name(e.name)) return here + ": the element name is not a name";
  if (e.line < 1 || e.line > lines)
    return here + ": line " + std::to_string(e.line) + " outside [1, " + std::to_string(lines) +
           "]";
  if (e.line < last_line)
    return here + ": line " + std::to_string(e.line) + " before the previous element's " +
           std::to_string(last_line);
  last_line = e.line;
  std::unordered_set<std::string_view> names;
  for (const auto& a : e.attributes) {
    if (!is_name(a.name)) return here + ": attribute " + c_literal(a.name) + " is not a name";
    if (!names.insert(a.name).second) return here + ": duplicate attribute " + c_literal(a.name);
  }
  for (const XmlElement& c : e.children) {
    std::string d = check_tree(c, depth + 1, lines, last_line, here);
    if (!d.empty()) return d;
  }
  return {};
}

// Where a and b first differ ("" if they are equal), lines left out.
std::string difference(const XmlElement& a, const XmlElement& b, const std::string& path) {
  const std::string here = path + "/" + a.name;
  if (a.name != b.name) return here + ": the name became " + c_literal(b.name);
  if (a.text != b.text)
    return here + ": the text " + c_literal(a.text) + " became " + c_literal(b.text);
  if (a.attributes.size() != b.attributes.size()) return here + ": the attribute counts differ";
  for (std::size_t k = 0; k < a.attributes.size(); ++k) {
    if (a.attributes[k].name != b.attributes[k].name)
      return here + ": attribute " + c_literal(a.attributes[k].name) + " became " +
             c_literal(b.attributes[k].name);
    if (a.attributes[k].value != b.attributes[k].value)
      return here + ": the value of " + c_literal(a.attributes[k].name) + ", " +
             c_literal(a.attributes[k].value) + ", became " + c_literal(b.attributes[k].value);
  }
  if (a.children.size() != b.children.size()) return here + ": the child counts differ";
  for (std::size_t k = 0; k < a.children.size(); ++k) {
    std::string d = difference(a.children[k], b.children[k], here);
    if (!d.empty()) return d;
  }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const int lines = line_count(text);
    XmlDocument doc;
    try {
      doc = topograsp::parse_xml(text, k_file);
    } catch (const topograsp::xml_error& e) {
      // The documented error: it must name the file and a line of the text.
      const std::string prefix = std::string(k_file) + ":" + std::to_string(e.line()) + ": ";
      if (e.file() != k_file || e.line() < 1 || e.line() > lines ||
          std::string_view(e.what()).substr(0, prefix.size()) != prefix)
        fuzz_fail("xml",
                  "the xml_error does not name the file and a line in [1, " +
                      std::to_string(lines) + "]: " + c_literal(e.what()),
                  "text = " + c_literal(text));
      return;
    } catch (const std::exception& e) {
      fuzz_fail("xml",
                std::string("parse_xml threw ") + typeid(e).name() +
                    " (not topograsp::xml_error): " + e.what(),
                "text = " + c_literal(text));
    }
    int last_line = 0;
    if (const std::string bad = check_tree(doc.root, 1, lines, last_line, ""); !bad.empty())
      fuzz_fail("xml", "parse_xml accepted a bad tree: " + bad, "text = " + c_literal(text));
    std::string written;
    write(written, doc.root);
    XmlDocument again;
    try {
      again = topograsp::parse_xml(written, k_file);
    } catch (const std::exception& e) {
      fuzz_fail("xml", std::string("the written document does not parse: ") + e.what(),
                "text = " + c_literal(text) + "\nwritten = " + c_literal(written));
    }
    if (const std::string d = difference(doc.root, again.root, ""); !d.empty())
      fuzz_fail("xml", "writing and parsing changed the tree",
                "text = " + c_literal(text) + "\nwritten = " + c_literal(written) + "\nat " + d);
  });
}
