// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// parse_xml() and read_xml_file(): a small, strict, non-validating XML reader for robot model
/// files (URDF, MJCF), with the line of every element and errors that name the file and line.
///
/// What it reads (XML 1.0 well-formedness, without a DTD):
/// - an optional UTF-8 byte order mark; the text is UTF-8 (or ASCII) and its bytes >= 0x80 are
///   passed through unchecked; a UTF-16 byte order mark is refused;
/// - the XML declaration and other processing instructions `<?target ...?>`, skipped;
/// - comments `<!-- ... -->`, skipped ("--" inside is tolerated);
/// - one `<!DOCTYPE ...>` before the root element, with an optional internal subset `[...]`,
///   skipped: the entities it declares are NOT supported (a reference to one is an unknown
///   entity), nor are its default attribute values;
/// - start, end and empty-element tags; attributes quoted with ' or ", with optional whitespace
///   around '='; names made of ASCII letters, digits, '_', '-', '.', ':' and bytes >= 0x80, not
///   starting with a digit, '-' or '.' (namespace prefixes are kept as part of the name);
/// - in text and attribute values the predefined entities &amp; &lt; &gt; &apos; &quot; and the
///   character references &#N; and &#xH; (as UTF-8; code point 0, surrogates and code points
///   above 0x10FFFF are refused); CDATA sections `<![CDATA[ ... ]]>` in text, taken literally.
///
/// Line ends are normalised as XML says: "\r\n" and a lone '\r' become '\n' in text, and every
/// literal tab, line end or '\r' of an attribute value becomes a space (a character reference
/// such as &#10; is kept as the character). Lines are counted at '\n', "\r\n" and a lone '\r'.
///
/// Everything else is an error (topograsp::xml_error, "FILE:LINE: problem"): unexpected end of
/// input, an end tag that does not match its start tag, a duplicate attribute, an attribute value
/// without quotes or with a '<', a bare '&' or an unknown entity, "]]>" in text, a control
/// character other than tab, '\n' and '\r' (raw, anywhere in the text), text or elements before
/// or after the root element (only whitespace, comments and processing instructions may be
/// there), no root element, and elements nested deeper than k_xml_max_depth. The parser is
/// iterative and linear in the size of the text.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>

#include <topograsp/io/detail/xml_parse.hpp>
#include <topograsp/io/xml_document.hpp>

namespace topograsp {

/// Parses the XML document \p text (see the file comment for what is read and refused).
/// \param[in] text The document.
/// \param[in] file Its file name, used only in error messages.
/// \throws topograsp::xml_error "FILE:LINE: problem" for text that is not well-formed.
[[nodiscard]] inline XmlDocument parse_xml(std::string_view text, std::string_view file) {
  return detail::XmlParser(text, file).parse();
}

/// Reads and parses the XML file at \p path (parse_xml(), with \p path as the file name).
/// \throws topograsp::xml_error "PATH: cannot be opened" (line 0) if the file cannot be opened
/// (or is a folder), "PATH: cannot be read" if reading fails, and parse_xml()'s errors.
[[nodiscard]] inline XmlDocument read_xml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw xml_error(path, 0, "cannot be opened (a folder)");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw xml_error(path, 0, "cannot be opened");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) throw xml_error(path, 0, "cannot be read");
  return parse_xml(text, path);
}

}  // namespace topograsp
