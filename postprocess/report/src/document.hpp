#pragma once
// The page as a list of blocks (document.cpp): the sections fill it, the renderers
// (render.cpp) write it as HTML and as Markdown.

#include "impact_postprocess/report/report.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace impact::postprocess::detail {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// A figure placed on the page: its path relative to the page, and caption.
struct PageFigure {
  std::string file;
  std::string caption;
};

struct Block {
  enum class Kind { heading, paragraph, warning, list, table, figure, code } kind;
  int level = 2;
  std::string text;
  std::vector<std::string> items;
  Table table;
  PageFigure figure;
  /// A section heading (level 2) that opens a section the reader can fold (HTML <details>,
  /// closed until opened); the section ends at the next level-2 heading.
  bool foldable = false;
};

/// The page as a list of blocks. The first screen (the title, the verdict in three lines,
/// the first figure, the recommended model) comes first; after fold_from_here() every
/// section (level-2 heading) can be folded.
class Document {
public:
  void heading(const std::string& text, int level = 2) {
    blocks.push_back({Block::Kind::heading, level, text, {}, {}, {}, folding && level == 2});
  }
  /// Every section from here on can be folded.
  void fold_from_here() { folding = true; }
  void paragraph(const std::string& text) {
    blocks.push_back({Block::Kind::paragraph, 0, text, {}, {}, {}});
  }
  /// A paragraph shown as a warning (red in the HTML).
  void warning(const std::string& text) {
    blocks.push_back({Block::Kind::warning, 0, text, {}, {}, {}});
  }
  void list(std::vector<std::string> items) {
    if (!items.empty()) blocks.push_back({Block::Kind::list, 0, "", std::move(items), {}, {}});
  }
  void table(Table table) {
    blocks.push_back({Block::Kind::table, 0, "", {}, std::move(table), {}});
  }
  void figure(const PageFigure& figure) {
    blocks.push_back({Block::Kind::figure, 0, "", {}, {}, figure});
  }
  void code(const std::string& text) { blocks.push_back({Block::Kind::code, 0, text, {}, {}, {}}); }
  std::vector<Block> blocks;

private:
  bool folding = false;
};

Document build_document(const Report& report, const std::filesystem::path& figures_directory);

/// Places a declared figure on the page (nothing when it is not declared); the key names
/// the map model of a validity map.
using FigurePlacer = std::function<void(FigureId, const std::string& model_key)>;

} // namespace impact::postprocess::detail
