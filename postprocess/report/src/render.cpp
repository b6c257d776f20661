// The two renderings of the report's page (document.hpp): Markdown, with the
// figures referenced beside it, and one self-contained HTML file with the figures embedded.

#include "sections.hpp"

#include <fstream>
#include <sstream>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;
using detail::Block;
using detail::build_document;
using detail::Document;

// ---- Rendering ------------------------------------------------------------------------

// The space before a "%" is a non-breaking one, so that a narrow table cell never splits a
// number from its unit ("+4.67" over "%").
std::string escape_html(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ' && i + 1 < text.size() && text[i + 1] == '%') {
      out += "&nbsp;";
      continue;
    }
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string escape_markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    for (int shift : {18, 12, 6, 0}) out += alphabet[(v >> shift) & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string read_binary(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_atomically(const fs::path& file, const std::string& text) {
  const fs::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, file);
}

} // namespace

void write_report_markdown(const Report& report, const fs::path& file,
                           const fs::path& figures_directory) {
  const Document doc = build_document(report, figures_directory);
  std::ostringstream out;
  for (const auto& block : doc.blocks) {
    switch (block.kind) {
      case Block::Kind::heading:
        out << std::string(block.level, '#') << ' ' << block.text << "\n\n";
        break;
      case Block::Kind::paragraph:
      case Block::Kind::warning:
        out << block.text << "\n\n";
        break;
      case Block::Kind::list:
        for (const auto& item : block.items) out << "- " << item << '\n';
        out << '\n';
        break;
      case Block::Kind::code:
        out << "```\n" << block.text << "\n```\n\n";
        break;
      case Block::Kind::table: {
        const auto row = [&](const std::vector<std::string>& cells) {
          out << '|';
          for (const auto& c : cells) out << ' ' << escape_markdown_cell(c) << " |";
          out << '\n';
        };
        row(block.table.header);
        out << '|';
        for (std::size_t i = 0; i < block.table.header.size(); ++i) out << "---|";
        out << '\n';
        for (const auto& r : block.table.rows) row(r);
        out << '\n';
        break;
      }
      case Block::Kind::figure: {
        const fs::path image = file.parent_path() / block.figure.file;
        if (fs::exists(image) && fs::file_size(image) > 0)
          out << "![" << block.figure.caption << "](" << block.figure.file << ")\n\n*"
              << block.figure.caption << "*\n\n";
        else
          out << "*Figure missing (" << block.figure.file
              << " was not drawn, see Status): " << block.figure.caption << "*\n\n";
        break;
      }
    }
  }
  write_atomically(file, out.str());
}

void write_report_html(const Report& report, const fs::path& file,
                       const fs::path& figures_directory) {
  const Document doc = build_document(report, figures_directory);
  std::ostringstream out;
  // Nothing may scroll sideways at 1280 px: the page is at most 1150 px wide, a table wraps
  // its cells at spaces (the tables are made narrow enough for that: tests/postprocess
  // measure it), a code block wraps its lines and a figure shrinks to the page. The first screen (before the first foldable section) is compact, so that the
  // verdict, the first figure and the recommended model fit one screen.
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>Impact model-validity report</title>\n<style>\n"
         "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:.6em auto;max-width:1150px;"
         "color:#222;line-height:1.4;padding:0 1em}\n"
         "h1{border-bottom:3px solid #b22;padding-bottom:.1em;margin:.2em 0 .3em;font-size:1.6em}\n"
         "summary h2{margin:0;font-size:1.3em;display:inline}h3{margin-top:1.2em}\n"
         "details{border-bottom:1px solid #ccc;padding:.45em 0}\n"
         "summary{cursor:pointer}details[open]>summary{margin-bottom:.6em}\n"
         "table{border-collapse:collapse;margin:.6em 0 1.2em;font-size:.85em;max-width:100%}\n"
         "th,td{border:1px solid #bbb;padding:.25em .5em;text-align:right}\n"
         "th{background:#eef2f7}td:first-child,th:first-child{text-align:left}\n"
         "tr:nth-child(even) td{background:#fafafa}\n"
         "figure{margin:.4em 0}figure img{max-width:100%;height:auto;border:1px solid #ddd}\n"
         "figcaption{font-style:italic;color:#555;font-size:.85em}\n"
         "pre{background:#f4f4f4;padding:.5em .8em;border-left:4px solid #b22;white-space:pre-wrap;"
         "overflow-wrap:anywhere;margin:.4em 0}\n"
         ".glance ul{margin:.2em 0;padding-left:1.3em}.glance li{margin:.15em 0}\n"
         ".glance p{margin:.3em 0}\n"
         // The glance's figure a little lower than the page is wide, so that the recommended
         // law's block below it stays on the first screen after the glance's lines.
         ".glance figure img{max-height:300px;width:auto}\n"
         ".missing{color:#b22;font-weight:bold}\n"
         "</style>\n</head>\n<body>\n<div class=\"glance\">\n";
  bool glance = true, section_open = false;
  const auto close_section = [&] {
    if (glance) out << "</div>\n";
    if (section_open) out << "</details>\n";
    glance = section_open = false;
  };
  for (const auto& block : doc.blocks) {
    switch (block.kind) {
      case Block::Kind::heading:
        if (block.foldable) {
          close_section();
          out << "<details><summary><h2>" << escape_html(block.text) << "</h2></summary>\n";
          section_open = true;
          break;
        }
        out << "<h" << block.level << '>' << escape_html(block.text) << "</h" << block.level
            << ">\n";
        break;
      case Block::Kind::paragraph:
        out << "<p>" << escape_html(block.text) << "</p>\n";
        break;
      case Block::Kind::warning:
        out << "<p class=\"missing\">" << escape_html(block.text) << "</p>\n";
        break;
      case Block::Kind::list:
        out << "<ul>\n";
        for (const auto& item : block.items) out << "<li>" << escape_html(item) << "</li>\n";
        out << "</ul>\n";
        break;
      case Block::Kind::code:
        out << "<pre>" << escape_html(block.text) << "</pre>\n";
        break;
      case Block::Kind::table:
        out << "<table>\n<tr>";
        for (const auto& c : block.table.header) out << "<th>" << escape_html(c) << "</th>";
        out << "</tr>\n";
        for (const auto& r : block.table.rows) {
          out << "<tr>";
          for (const auto& c : r) out << "<td>" << escape_html(c) << "</td>";
          out << "</tr>\n";
        }
        out << "</table>\n";
        break;
      case Block::Kind::figure: {
        const fs::path image = file.parent_path() / block.figure.file;
        if (fs::exists(image) && fs::file_size(image) > 0)
          out << "<figure><img alt=\"" << escape_html(block.figure.caption)
              << "\" src=\"data:image/png;base64," << base64(read_binary(image))
              << "\"><figcaption>" << escape_html(block.figure.caption)
              << "</figcaption></figure>\n";
        else
          out << "<p class=\"missing\">Figure missing (" << escape_html(block.figure.file)
              << " was not drawn, see Status): " << escape_html(block.figure.caption) << "</p>\n";
        break;
      }
    }
  }
  close_section();
  out << "</body>\n</html>\n";
  write_atomically(file, out.str());
}

} // namespace impact::postprocess
