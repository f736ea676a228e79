// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The parser behind parse_xml() (io/xml.hpp; internal), which documents what it reads and refuses.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include <topograsp/io/detail/utf8.hpp>
#include <topograsp/io/xml_document.hpp>

namespace topograsp::detail {

/// The parser behind parse_xml(): one pass over the text with an explicit stack of open elements
/// (no recursion), so hostile input can exhaust neither the stack nor the time.
class XmlParser {
 public:
  XmlParser(std::string_view text, std::string_view file) : t_(text), file_(file) {}

  XmlDocument parse() {
    if (t_.substr(0, 3) == "\xEF\xBB\xBF") {
      pos_ = 3;
      counted_ = 3;
    } else if (t_.substr(0, 2) == "\xFE\xFF" || t_.substr(0, 2) == "\xFF\xFE") {
      fail(0, "UTF-16 is not supported (expected UTF-8)");
    }
    check_characters();
    XmlDocument doc;
    doc.file = std::string(file_);
    std::vector<XmlElement> open;  // the elements whose end tag is still to come
    bool have_root = false;
    bool have_doctype = false;
    while (true) {
      if (open.empty()) {
        // Before or after the root element: whitespace, comments and processing instructions.
        skip_space();
        if (at_end()) break;
        if (t_[pos_] != '<')
          fail(pos_, have_root ? "text after the root element <" + doc.root.name + ">"
                               : std::string("text before the root element"));
        if (starts("<?")) {
          skip_processing_instruction();
        } else if (starts("<!--")) {
          skip_comment();
        } else if (starts("<!DOCTYPE")) {
          if (have_root || have_doctype)
            fail(pos_, have_root ? "<!DOCTYPE> after the root element" : "a second <!DOCTYPE>");
          skip_doctype();
          have_doctype = true;
        } else if (starts("<![CDATA[")) {
          fail(pos_, "CDATA section outside the root element");
        } else if (starts("<!")) {
          fail(pos_, "unknown markup '<!' (expected a comment '<!--')");
        } else if (starts("</")) {
          const std::size_t at = pos_;
          pos_ += 2;
          const std::string_view name = read_name("an element name after '</'");
          fail(at, "end tag </" + std::string(name) + "> without a start tag");
        } else {
          const std::size_t at = pos_;
          bool empty = false;
          XmlElement e = read_start_tag(empty);
          if (have_root)
            fail(at, "element <" + e.name + "> after the root element <" + doc.root.name + ">");
          have_root = true;
          if (empty)
            doc.root = std::move(e);
          else
            open.push_back(std::move(e));
        }
        continue;
      }
      // Inside an element: text, references, CDATA, comments, PIs, child elements, end tag.
      XmlElement& current = open.back();
      read_text(current.text);
      if (at_end())
        fail_end("<" + current.name + "> (line " + std::to_string(current.line) +
                 ") is not closed");
      if (starts("<!--")) {
        skip_comment();
      } else if (starts("<?")) {
        skip_processing_instruction();
      } else if (starts("<![CDATA[")) {
        read_cdata(current.text);
      } else if (starts("<!DOCTYPE")) {
        fail(pos_, "<!DOCTYPE> inside an element (it may only come before the root element)");
      } else if (starts("<!")) {
        fail(pos_, "unknown markup '<!' (expected a comment '<!--' or '<![CDATA[')");
      } else if (starts("</")) {
        read_end_tag(current);
        XmlElement done = std::move(open.back());
        open.pop_back();
        if (open.empty())
          doc.root = std::move(done);
        else
          open.back().children.push_back(std::move(done));
      } else {
        if (open.size() >= static_cast<std::size_t>(k_xml_max_depth))
          fail(pos_, "elements nested deeper than " + std::to_string(k_xml_max_depth) +
                         " levels (inside <" + current.name + ">)");
        bool empty = false;
        XmlElement e = read_start_tag(empty);
        if (empty)
          current.children.push_back(std::move(e));
        else
          open.push_back(std::move(e));  // invalidates current
      }
    }
    if (!have_root) fail_end_line("no root element");
    return doc;
  }

 private:
  // ---- errors and lines

  // The 1-based line of offset p. Lines are counted incrementally for the increasing offsets of
  // the parse; an earlier offset (an error's) is counted from the start.
  int line_at(std::size_t p) {
    if (p < counted_) {
      counted_ = 0;
      line_ = 1;
    }
    for (; counted_ < p && counted_ < t_.size(); ++counted_) {
      const char c = t_[counted_];
      if (c == '\n' || (c == '\r' && (counted_ + 1 >= t_.size() || t_[counted_ + 1] != '\n')))
        ++line_;
    }
    return line_;
  }
  [[noreturn]] void fail(std::size_t p, const std::string& problem) {
    throw xml_error(std::string(file_), line_at(p), problem);
  }
  // An error at the end of the text, reported at the line of its last character.
  [[noreturn]] void fail_end_line(const std::string& problem) {
    fail(t_.empty() ? 0 : t_.size() - 1, problem);
  }
  [[noreturn]] void fail_end(const std::string& what) {
    fail_end_line("unexpected end of input: " + what);
  }

  // ---- characters

  static bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  static bool is_name_start(char c) noexcept {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
           static_cast<unsigned char>(c) >= 0x80;
  }
  static bool is_name_char(char c) noexcept {
    return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
  }
  [[nodiscard]] bool at_end() const noexcept { return pos_ >= t_.size(); }
  [[nodiscard]] bool starts(std::string_view s) const noexcept {
    return t_.substr(pos_, s.size()) == s;
  }
  void skip_space() noexcept {
    while (pos_ < t_.size() && is_space(t_[pos_])) ++pos_;
  }
  // XML 1.0 allows no control character but tab, '\n' and '\r'.
  void check_characters() {
    for (std::size_t p = pos_; p < t_.size(); ++p) {
      const auto u = static_cast<unsigned char>(t_[p]);
      if (u < 0x20 && u != '\t' && u != '\n' && u != '\r') {
        static constexpr char k_hex[] = "0123456789abcdef";
        fail(p, std::string("control character 0x") + k_hex[u >> 4] + k_hex[u & 15u] +
                    " is not allowed in XML");
      }
    }
  }
  // The name at pos_ (a view into the text), or an error saying \p what was expected.
  std::string_view read_name(const char* what) {
    if (at_end()) fail_end(std::string("expected ") + what);
    if (!is_name_start(t_[pos_])) fail(pos_, std::string("expected ") + what);
    const std::size_t start = pos_;
    while (pos_ < t_.size() && is_name_char(t_[pos_])) ++pos_;
    return t_.substr(start, pos_ - start);
  }

  // ---- markup that is skipped

  void skip_comment() {  // at "<!--"
    const std::size_t start = pos_;
    const std::size_t end = t_.find("-->", pos_ + 4);
    if (end == std::string_view::npos)
      fail_end("the comment at line " + std::to_string(line_at(start)) + " is not closed by '-->'");
    pos_ = end + 3;
  }
  void skip_processing_instruction() {  // at "<?"
    const std::size_t start = pos_;
    pos_ += 2;
    (void)read_name("a name after '<?'");
    const std::size_t end = t_.find("?>", pos_);
    if (end == std::string_view::npos)
      fail_end("the processing instruction at line " + std::to_string(line_at(start)) +
               " is not closed by '?>'");
    pos_ = end + 2;
  }
  // Skips from the quote at pos_ to after the matching one.
  void skip_quoted(std::size_t start) {
    const std::size_t end = t_.find(t_[pos_], pos_ + 1);
    if (end == std::string_view::npos)
      fail_end("a quoted string in the <!DOCTYPE> at line " + std::to_string(line_at(start)) +
               " is not closed");
    pos_ = end + 1;
  }
  void skip_doctype() {  // at "<!DOCTYPE"
    const std::size_t start = pos_;
    pos_ += 9;
    if (!at_end() && !is_space(t_[pos_])) fail(pos_, "expected whitespace after '<!DOCTYPE'");
    const auto unclosed = [&] {
      fail_end("the <!DOCTYPE> at line " + std::to_string(line_at(start)) + " is not closed");
    };
    while (true) {
      if (at_end()) unclosed();
      const char c = t_[pos_];
      if (c == '>') {
        ++pos_;
        return;
      }
      if (c == '"' || c == '\'') {
        skip_quoted(start);
      } else if (c == '[') {
        // The internal subset: declarations, comments and PIs up to the closing ']'.
        ++pos_;
        while (true) {
          if (at_end()) unclosed();
          const char d = t_[pos_];
          if (d == ']') {
            ++pos_;
            break;
          }
          if (d == '"' || d == '\'')
            skip_quoted(start);
          else if (starts("<!--"))
            skip_comment();
          else if (starts("<?"))
            skip_processing_instruction();
          else
            ++pos_;
        }
      } else {
        ++pos_;
      }
    }
  }

  // ---- text

  // Decodes the reference at pos_ ('&') into \p out.
  void read_reference(std::string& out) {
    const std::size_t start = pos_;
    ++pos_;
    if (!at_end() && t_[pos_] == '#') {
      ++pos_;
      const bool hex = !at_end() && t_[pos_] == 'x';
      if (hex) ++pos_;
      unsigned long cp = 0;
      std::size_t digits = 0;
      for (; !at_end(); ++pos_, ++digits) {
        const char c = t_[pos_];
        unsigned d = 0;
        if (c >= '0' && c <= '9')
          d = static_cast<unsigned>(c - '0');
        else if (hex && c >= 'a' && c <= 'f')
          d = static_cast<unsigned>(c - 'a') + 10u;
        else if (hex && c >= 'A' && c <= 'F')
          d = static_cast<unsigned>(c - 'A') + 10u;
        else
          break;
        cp = cp * (hex ? 16u : 10u) + d;
        if (cp > 0x110000u) cp = 0x110000u;  // saturates: any larger value is refused alike
      }
      if (at_end()) fail_end("in a character reference");
      if (digits == 0 || t_[pos_] != ';')
        fail(start,
             hex ? "bad character reference (expected &#xH; with hex digits H)"
                 : "bad character reference (expected &#N; with decimal digits N, or &#xH;)");
      ++pos_;
      if (cp == 0 || (cp >= 0xD800u && cp <= 0xDFFFu) || cp > 0x10FFFFu)
        fail(start, "character reference " + std::string(t_.substr(start, pos_ - start)) +
                        " is not a valid character (0, a surrogate or above 0x10FFFF)");
      detail::append_utf8(out, static_cast<unsigned>(cp));
      return;
    }
    const std::size_t name_start = pos_;
    while (pos_ < t_.size() && is_name_char(t_[pos_])) ++pos_;
    if (at_end()) fail_end("in an entity reference");
    if (pos_ == name_start || t_[pos_] != ';')
      fail(start, "'&' that does not start an entity reference (write &amp; for '&')");
    const std::string_view name = t_.substr(name_start, pos_ - name_start);
    ++pos_;
    if (name == "amp")
      out += '&';
    else if (name == "lt")
      out += '<';
    else if (name == "gt")
      out += '>';
    else if (name == "apos")
      out += '\'';
    else if (name == "quot")
      out += '"';
    else
      fail(start, "unknown entity &" + std::string(name) +
                      "; (only &amp; &lt; &gt; &apos; &quot; and character references; entities "
                      "of a <!DOCTYPE> are not supported)");
  }
  // Character data up to the next '<' (or the end), appended to \p out.
  void read_text(std::string& out) {
    while (pos_ < t_.size()) {
      const char c = t_[pos_];
      if (c == '<') return;
      if (c == '&') {
        read_reference(out);
      } else if (c == '\r') {
        out += '\n';
        pos_ += starts("\r\n") ? 2u : 1u;
      } else if (c == ']') {
        if (starts("]]>")) fail(pos_, "']]>' in text (write ]]&gt;)");
        out += c;
        ++pos_;
      } else {
        // A run of plain characters, appended at once.
        const std::size_t end = std::min(t_.find_first_of("<&\r]", pos_), t_.size());
        out.append(t_.data() + pos_, end - pos_);
        pos_ = end;
      }
    }
  }
  void read_cdata(std::string& out) {  // at "<![CDATA["
    const std::size_t start = pos_;
    const std::size_t end = t_.find("]]>", pos_ + 9);
    if (end == std::string_view::npos)
      fail_end("the CDATA section at line " + std::to_string(line_at(start)) +
               " is not closed by ']]>'");
    for (std::size_t p = pos_ + 9; p < end; ++p) {
      if (t_[p] != '\r')
        out += t_[p];
      else if (p + 1 >= end || t_[p + 1] != '\n')
        out += '\n';
    }
    pos_ = end + 3;
  }

  // ---- tags

  // The start tag at pos_ ('<'): the element with its name, line and attributes; \p empty is set
  // for an empty-element tag "<name .../>".
  XmlElement read_start_tag(bool& empty) {
    XmlElement e;
    e.line = line_at(pos_);
    ++pos_;
    e.name = std::string(read_name("an element name after '<'"));
    std::vector<std::string_view> names;            // the attribute names, views into the text
    std::unordered_set<std::string_view> name_set;  // the same, once there are many
    constexpr std::size_t k_linear = 16;
    while (true) {
      const std::size_t before_space = pos_;
      skip_space();
      if (at_end()) fail_end("in the start tag <" + e.name + ">");
      const char c = t_[pos_];
      if (c == '>') {
        ++pos_;
        empty = false;
        return e;
      }
      if (c == '/' && starts("/>")) {
        pos_ += 2;
        empty = true;
        return e;
      }
      if (!is_name_start(c)) fail(pos_, "expected '>' to close <" + e.name + ">");
      const std::size_t name_at = pos_;
      const std::string_view name = read_name("an attribute name");
      if (name_at == before_space)
        fail(name_at, "expected whitespace before attribute '" + std::string(name) + "' in <" +
                          e.name + ">");
      bool duplicate = false;
      if (names.size() < k_linear) {
        for (const std::string_view n : names) duplicate = duplicate || n == name;
        names.push_back(name);
        if (names.size() == k_linear) name_set.insert(names.begin(), names.end());
      } else {
        duplicate = !name_set.insert(name).second;
      }
      if (duplicate)
        fail(name_at, "duplicate attribute '" + std::string(name) + "' in <" + e.name + ">");
      skip_space();
      if (at_end()) fail_end("in the start tag <" + e.name + ">");
      if (t_[pos_] != '=')
        fail(pos_, "expected '=' after attribute '" + std::string(name) + "' in <" + e.name + ">");
      ++pos_;
      skip_space();
      if (at_end()) fail_end("in the start tag <" + e.name + ">");
      const char quote = t_[pos_];
      if (quote != '"' && quote != '\'')
        fail(pos_, "expected a value in quotes (' or \") for attribute '" + std::string(name) +
                       "' in <" + e.name + ">");
      ++pos_;
      XmlAttribute a{std::string(name), {}};
      while (true) {
        if (at_end())
          fail_end("the value of attribute '" + a.name + "' in <" + e.name + "> is not closed by " +
                   (quote == '"' ? "'\"'" : "\"'\""));
        const char v = t_[pos_];
        if (v == quote) {
          ++pos_;
          break;
        }
        if (v == '<')
          fail(pos_,
               "'<' in the value of attribute '" + a.name + "' in <" + e.name + "> (write &lt;)");
        if (v == '&') {
          read_reference(a.value);
        } else if (v == '\t' || v == '\n' || v == '\r') {
          a.value += ' ';
          pos_ += starts("\r\n") ? 2u : 1u;
        } else {
          a.value += v;
          ++pos_;
        }
      }
      e.attributes.push_back(std::move(a));
    }
  }
  // The end tag at pos_ ("</"), which must close \p open.
  void read_end_tag(const XmlElement& open) {
    const std::size_t start = pos_;
    pos_ += 2;
    const std::string_view name = read_name("an element name after '</'");
    skip_space();
    if (at_end()) fail_end("in the end tag </" + std::string(name) + ">");
    if (t_[pos_] != '>') fail(pos_, "expected '>' to close </" + std::string(name) + ">");
    ++pos_;
    if (name != open.name)
      fail(start, "end tag </" + std::string(name) + "> does not match the start tag <" +
                      open.name + "> at line " + std::to_string(open.line));
  }

  std::string_view t_;
  std::string_view file_;
  std::size_t pos_ = 0;
  std::size_t counted_ = 0;  // line_ is the line of offset counted_
  int line_ = 1;
};

}  // namespace topograsp::detail
