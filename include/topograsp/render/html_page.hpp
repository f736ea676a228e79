// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// HtmlPage and write_html_page(): a self-contained results page (inline CSS) with a table and
/// figures referenced by relative path.
#pragma once

#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/io/text_file.hpp>

namespace topograsp {

/// An image on an HtmlPage and its caption.
struct HtmlFigure {
  std::string image;  ///< path relative to the page (e.g. "hammer_3.svg"); no scheme, not absolute
  std::string caption;  ///< text under the image
};

/// A results page: a title, an optional introduction, one table (a header row and rows of
/// strings) and figures, written by html_page() as one HTML file with inline CSS. Cells and
/// captions are text (escaped); cells that read as numbers are right-aligned, and cells that read
/// "stable" / "unstable" are coloured.
struct HtmlPage {
  std::string title;                           ///< page title and heading
  std::string intro;                           ///< a paragraph under the heading; may be empty
  std::vector<std::string> header;             ///< the table's column names; empty: no table
  std::vector<std::vector<std::string>> rows;  ///< each with as many cells as header
  std::vector<HtmlFigure> figures;             ///< shown in order under the table
};

namespace detail {

// True if s reads as a number (optionally signed, with a decimal point, an exponent, or a %).
inline bool html_numeric(std::string_view s) {
  if (s.empty()) return false;
  std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  bool digit = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (std::isdigit(static_cast<unsigned char>(c)))
      digit = true;
    else if (c != '.' && c != 'e' && c != 'E' && c != '-' && c != '+' &&
             !(c == '%' && i + 1 == s.size()))
      return false;
  }
  return digit;
}

// The relative path p percent-encoded for a src attribute (unreserved characters and '/' kept).
inline std::string html_url(std::string_view p) {
  std::string o;
  for (const char c : p) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      o += c;
    } else {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", static_cast<unsigned>(u));
      o += b;
    }
  }
  return o;
}

inline void check_html_page(const HtmlPage& page) {
  for (std::size_t r = 0; r < page.rows.size(); ++r)
    if (page.rows[r].size() != page.header.size())
      throw_invalid_argument("rows", "row " + std::to_string(r) + " has " +
                                         std::to_string(page.rows[r].size()) + " cells, expected " +
                                         std::to_string(page.header.size()));
  for (std::size_t f = 0; f < page.figures.size(); ++f) {
    const std::string& p = page.figures[f].image;
    if (p.empty() || p[0] == '/' || p[0] == '\\' || p.find(':') != std::string::npos)
      throw_invalid_argument("figures", "figure " + std::to_string(f) +
                                            ": expected a path relative to the page, got \"" + p +
                                            "\"");
  }
}

}  // namespace detail

/// The page as one HTML5 document (UTF-8, inline CSS, no scripts, images by relative path).
/// \throws topograsp::invalid_argument naming "rows" if a row has not as many cells as the
///         header, or "figures" if an image path is empty, absolute or has a scheme.
[[nodiscard]] inline std::string html_page(const HtmlPage& page) {
  detail::check_html_page(page);
  using detail::xml_escape;
  std::string o;
  o += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  o += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  o += "<title>" + xml_escape(page.title) + "</title>\n";
  o += "<style>\n"
       "body { font-family: sans-serif; margin: 2em auto; max-width: 1400px; padding: 0 1em;"
       " color: #222; }\n"
       "h1 { font-size: 1.6em; }\n"
       "table { border-collapse: collapse; margin: 1em 0; }\n"
       "th, td { border: 1px solid #ccc; padding: 0.3em 0.7em; text-align: left; }\n"
       "th { background: #f0f0f0; }\n"
       "tr:nth-child(even) td { background: #fafafa; }\n"
       "td.num { text-align: right; font-variant-numeric: tabular-nums; }\n"
       "td.stable { color: #1a7f37; font-weight: bold; }\n"
       "td.unstable { color: #c62828; font-weight: bold; }\n"
       "figure { margin: 1.5em 0; }\n"
       "figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }\n"
       "figcaption { color: #555; margin-top: 0.3em; }\n"
       "</style>\n</head>\n<body>\n";
  o += "<h1>" + xml_escape(page.title) + "</h1>\n";
  if (!page.intro.empty()) o += "<p>" + xml_escape(page.intro) + "</p>\n";
  if (!page.header.empty()) {
    o += "<table>\n<thead><tr>";
    for (const std::string& h : page.header) o += "<th>" + xml_escape(h) + "</th>";
    o += "</tr></thead>\n<tbody>\n";
    for (const auto& row : page.rows) {
      o += "<tr>";
      for (const std::string& cell : row) {
        const char* cls = detail::html_numeric(cell) ? " class=\"num\""
                          : cell == "stable"         ? " class=\"stable\""
                          : cell == "unstable"       ? " class=\"unstable\""
                                                     : "";
        o += std::string("<td") + cls + ">" + xml_escape(cell) + "</td>";
      }
      o += "</tr>\n";
    }
    o += "</tbody>\n</table>\n";
  }
  for (const HtmlFigure& f : page.figures) {
    o += "<figure>\n<img src=\"" + xml_escape(detail::html_url(f.image)) + "\" alt=\"" +
         xml_escape(f.caption.empty() ? f.image : f.caption) + "\">\n";
    if (!f.caption.empty()) o += "<figcaption>" + xml_escape(f.caption) + "</figcaption>\n";
    o += "</figure>\n";
  }
  o += "</body>\n</html>\n";
  return o;
}

/// Writes html_page(page) to \p path (e.g. "out/index.html"; the images are looked up relative
/// to its folder).
/// \throws topograsp::invalid_argument as html_page() does, or naming "path" if the file cannot
///         be written.
inline void write_html_page(const std::string& path, const HtmlPage& page) {
  detail::write_text_file(path, html_page(page));
}

}  // namespace topograsp
