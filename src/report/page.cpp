// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/page.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "report/number_format.hpp"

namespace armstudy::report {

void Section::paragraph(std::string text) {
  Block b;
  b.kind = Block::Kind::kParagraph;
  b.text = std::move(text);
  blocks.push_back(std::move(b));
}

void Section::note(std::string text) {
  Block b;
  b.kind = Block::Kind::kNote;
  b.text = std::move(text);
  blocks.push_back(std::move(b));
}

void Section::movies(std::vector<Movie> m) {
  Block b;
  b.kind = Block::Kind::kMovies;
  b.movies = std::move(m);
  blocks.push_back(std::move(b));
}

void Section::code(std::string text) {
  Block b;
  b.kind = Block::Kind::kCode;
  b.text = std::move(text);
  blocks.push_back(std::move(b));
}

void Section::table(Table t) {
  Block b;
  b.kind = Block::Kind::kTable;
  b.table = std::move(t);
  blocks.push_back(std::move(b));
}

void Section::figure(Figure f) {
  if (f.file.empty()) {
    note(std::move(f.caption));
    return;
  }
  // captions are sentences
  if (!f.caption.empty() && f.caption[0] >= 'a' && f.caption[0] <= 'z') f.caption[0] -= 'a' - 'A';
  Block b;
  b.kind = Block::Kind::kFigure;
  b.figure = std::move(f);
  blocks.push_back(std::move(b));
}

void Section::strip(Strip s) {
  Block b;
  b.kind = Block::Kind::kStrip;
  b.strip = std::move(s);
  blocks.push_back(std::move(b));
}

std::string FigureWriter::next_name(const std::string& name) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "fig%02d_", ++count_);
  std::string safe;
  for (char c : name)
    safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return buf + safe + ".svg";
}

// data that cannot be drawn (nothing finite, inconsistent sizes) costs the figure, not the
// report: the page says which figure is missing and why
Figure FigureWriter::line(const std::string& name, const LinePlot& plot, std::string caption) {
  const std::string file = next_name(name);
  try {
    write_line_plot(plot, dir_ / file);
  } catch (const std::invalid_argument& e) {
    return {"", "The figure '" + plot.title + "' could not be drawn: " + e.what()};
  }
  return {file, std::move(caption)};
}

Figure FigureWriter::map(const std::string& name, const ShadedMap& map, std::string caption) {
  const std::string file = next_name(name);
  try {
    write_shaded_map(map, dir_ / file);
  } catch (const std::invalid_argument& e) {
    return {"", "The figure '" + map.title + "' could not be drawn: " + e.what()};
  }
  return {file, std::move(caption)};
}

}  // namespace armstudy::report
