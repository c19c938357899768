// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The content model of a report page (sections of paragraphs, tables, figures and notes)
/// and the helpers that study sections use to fill it. Rendering to HTML happens in
/// html.hpp through the mustache templates; every string here is plain text and is
/// HTML-escaped there.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/answer_box.hpp"
#include "report/plot.hpp"

namespace armstudy::report {

/// A table: a header row and body rows of plain-text cells.
struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// Optional colour swatch per row ("#rrggbb", empty for none), shown before the first cell:
  /// ties a row to the colour of its curves in the plots.
  std::vector<std::string> swatches;
  /// A short table of few columns: printed at half the page width, beside the next narrow one.
  bool narrow = false;
};

/// A figure: an image file in the case folder (embedded as <img>, never inlined).
struct Figure {
  std::string file;     ///< relative to the case folder
  std::string caption;  ///< what it shows; the alt text too
  bool half = false;    ///< printed at half the page width, side by side with the next half
};

/// A strip of images (frames), each with a short label.
struct Strip {
  std::string caption;
  std::vector<std::string> files;
  std::vector<std::string> labels;
  std::vector<bool> wide;  ///< per file: a full-width image (a composed strip), else half
};

/// A moving picture of a motion: a CSS animation over a sprite sheet (no script), its
/// still for print, and the video file beside it.
struct Movie {
  std::string css_class;  ///< the stylesheet's rule for this sprite (letters, digits, '-', '_')
  std::string still;      ///< still image (printed, and shown when motion is reduced)
  std::string video;      ///< video file; empty: none
  std::string title;      ///< which motion
  std::string caption;    ///< speed, frames, how to pause
};

/// One element of a section, in reading order.
struct Block {
  enum class Kind { kParagraph, kNote, kTable, kFigure, kStrip, kCode, kMovies };
  Kind kind = Kind::kParagraph;
  std::string text;  ///< paragraph, note or code text
  Table table;
  Figure figure;
  Strip strip;
  std::vector<Movie> movies;  ///< kMovies: shown side by side
};

/// A section of the page (printed from a new page unless `new_page` is false).
struct Section {
  std::string id;  ///< HTML id (letters, digits, '-')
  std::string heading;
  bool new_page = true;
  std::vector<Block> blocks;

  /// Adds a paragraph of plain text.
  void paragraph(std::string text);
  /// An honest remark, e.g. where the source printed different numbers and why.
  void note(std::string text);
  /// Adds preformatted text (e.g. the case's YAML).
  void code(std::string text);
  /// Adds a table (never split across printed pages).
  void table(Table t);
  /// Adds the figure; one without a file (not drawable) becomes a note with its caption.
  void figure(Figure f);
  /// Adds a strip of images (frames).
  void strip(Strip s);
  /// Adds moving pictures, side by side.
  void movies(std::vector<Movie> m);
};

/// Everything a case page shows, filled by the generic writer and the study's section builder.
struct CasePage {
  std::string title;
  std::string study;
  std::string status;  ///< "solved" / "unsolvable"
  std::string message;
  std::string description;
  std::vector<std::pair<std::string, std::string>> key_figures;  ///< for the header and index
  std::vector<Section> sections;
  /// Header links (label, href); empty: "All cases" (../index.html) and the data link.
  std::vector<std::pair<std::string, std::string>> links;
  /// Whether the status badge is good news; unset: status == "solved".
  std::optional<bool> status_ok;
  /// Page 1's answer box (case pages); unset: the key figures in the header.
  std::optional<AnswerBox> answer;
};

/// `f` printed at half the page width, beside the next half one.
inline Figure half(Figure f) {
  f.half = true;
  return f;
}
/// `p` drawn for half the page width: a smaller drawing whose text prints larger.
inline LinePlot half_size(LinePlot p) {
  p.width_pt = 360;
  p.height_pt = 225;
  return p;
}

/// Writes the figures of one page into its folder with stable, ordered names
/// (fig01_<name>.svg, ...), so that the first figure can serve as the page's thumbnail.
class FigureWriter {
 public:
  explicit FigureWriter(std::filesystem::path dir) : dir_(std::move(dir)) {}
  /// Draws `plot` into the folder and returns the figure (file name relative to the folder).
  /// Data that cannot be drawn gives a figure with no file whose caption says why (the
  /// section shows it as a note). @throws std::runtime_error when the file cannot be written.
  Figure line(const std::string& name, const LinePlot& plot, std::string caption);
  /// Draws `map` into the folder and returns the figure (no file when the data cannot be
  /// drawn, as line()). @throws std::runtime_error when the file cannot be written.
  Figure map(const std::string& name, const ShadedMap& map, std::string caption);
  /// The folder the figures go to.
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::string next_name(const std::string& name);
  std::filesystem::path dir_;
  int count_ = 0;
};

}  // namespace armstudy::report
