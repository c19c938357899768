// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/case_report.hpp"

#include "sys/atomic_file.hpp"

#include <yaml-cpp/yaml.h>
#include <kainjow/mustache.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "cases/input_file.hpp"
#include "report/animation_view.hpp"
#include "report/number_format.hpp"
#include "report/owned_output.hpp"
#include "report/page.hpp"
#include "report/results_record.hpp"
#include "report/sensitivity_section.hpp"
#include "report/source_comparison.hpp"
#include "report/study_sections.hpp"
#include "report/templates.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;
namespace mus = kainjow::mustache;

namespace {

// the largest results.json the run's index reads (as merge and diff, docs/budgets.md)
constexpr std::uintmax_t kMaxIndexedResultsBytes = std::uintmax_t(16) << 20;
std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// through a temporary file, removed on failure; the error says why (disk full, ...)
void write_text(const fs::path& p, const std::string& text) { sys::write_file_atomic(p, text); }

}  // namespace

namespace {

// {{x}} of a page: & < > " ' as entities, and a control character (but tab, newline and
// carriage return: an ESC of a description's "\e[31m") as the visible text \xNN
std::string page_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if ((c < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') || c == 0x7F) {
          char hex[8];
          std::snprintf(hex, sizeof hex, "\\x%02X", c);
          out += hex;
        } else {
          out += ch;
        }
    }
  }
  return out;
}

// renders a template of template_dir(); {{x}} escapes html (& < > " '), {{{x}}} is never used
std::string render_template(const std::string& name, const mus::data& data) {
  mus::mustache tmpl{read_template(template_dir() / name)};
  tmpl.set_custom_escape(page_escape);
  if (!tmpl.is_valid()) throw std::runtime_error("template " + name + ": " + tmpl.error_message());
  std::string html = tmpl.render(data);
  if (!tmpl.error_message().empty())
    throw std::runtime_error("template " + name + ": " + tmpl.error_message());
  return html;
}

// the template's stylesheet plus one swatch class per plot colour (the page's CSP forbids
// inline styles, so a table row's colour is a class: .swatch.c0072b2)
void copy_stylesheet(const fs::path& dir) {
  std::string css = read_template(template_dir() / "report.css");
  css += "\n/* plot colours, generated */\n";
  for (const Rgb& c : palette_colours()) {
    const std::string hex = css_colour(c);
    css += ".swatch.c" + hex.substr(1) + " { background: " + hex + "; }\n";
  }
  write_text(dir / "report.css", css);
}

Section case_section(const cases::CaseInfo& info) {
  Section s;
  s.id = "case";
  s.heading = "The case";
  s.new_page = false;
  // the file as written (keys carry their unit); the study's parameter table lists the
  // defaults it filled in
  s.paragraph("The case file " + fs::path(info.path).filename().string() +
              " as written (keys carry their unit):");
  s.code(info.yaml);
  return s;
}

// page 1 is the answer; the details follow from page 2 as one part, then the appendix:
// only the details start a printed page (a page per section left most of them half empty)
void lay_out_case_page(const nlohmann::json& results, StudyAnswer answer, CasePage& page) {
  page.answer = answer_box(results, page, answer);
  // the study's full parameter tables are reference material: to the appendix, in words
  Section params;
  params.id = "parameters";
  params.heading = "Appendix A. Parameters used";
  for (Section& s : page.sections)
    for (auto b = s.blocks.begin(); b != s.blocks.end();) {
      if (b->kind == Block::Kind::kTable && b->table.caption.starts_with("Parameters used")) {
        Table t = std::move(b->table);
        t.caption = "Parameters the study used, the defaults it filled in included (SI units).";
        for (auto& row : t.rows) {
          if (row.empty()) continue;
          std::string words, part;
          std::stringstream in(row[0]);
          while (std::getline(in, part, '.'))
            words += (words.empty() ? "" : ", ") + label_from_key(part);
          row[0] = words;
        }
        params.table(std::move(t));
        b = s.blocks.erase(b);
      } else {
        ++b;
      }
    }
  if (!params.blocks.empty()) {
    auto at = std::find_if(page.sections.begin(), page.sections.end(),
                           [](const Section& s) { return s.id == "case"; });
    page.sections.insert(at, std::move(params));
  }
  const bool has_params = std::any_of(page.sections.begin(), page.sections.end(),
                                      [](const Section& s) { return s.id == "parameters"; });
  for (size_t k = 0; k < page.sections.size(); ++k) {
    Section& s = page.sections[k];
    // the appendix follows on the same page: a forced break left the last rows of a long
    // table alone on a page
    s.new_page = k == 0;
    if (s.id == "case")
      s.heading = has_params ? "Appendix B. The case file" : "Appendix A. The case file";
    if (s.id == "provenance")
      s.heading = has_params ? "Appendix C. Provenance" : "Appendix B. Provenance";
  }
}

Section checks_section(const ResultsRecord& record) {
  Section s;
  s.id = "checks";
  s.heading = "Checks the study ran on its answer";
  Table t;
  t.header = {"check", "what it verifies", "value", "tolerance", "result"};
  for (const CheckRecord& c : record.checks)
    t.rows.push_back({check_label(c.name), c.description, format_sig(c.value, 4),
                      format_sig(c.tolerance, 3), c.passed ? "passed" : "FAILED"});
  if (t.rows.empty())
    s.paragraph("The study reported no checks for this case.");
  else
    s.table(std::move(t));
  return s;
}

// what a frame file shows, from the scene's names: <study>[_<what>][_c<N>]_{strip,locus}.png
std::string frame_label(const std::string& file, bool* wide) {
  std::string stem = fs::path(file).stem().string();
  std::string kind;
  for (const char* k : {"_strip", "_locus"})
    if (stem.size() > std::strlen(k) && stem.ends_with(k)) {
      kind = k + 1;
      stem.resize(stem.size() - std::strlen(k));
    }
  *wide = kind == "strip";
  // "placement_cycloidal_c1" -> "placement, cycloidal, configuration 1"
  std::string words;
  std::stringstream in(stem);
  std::string w;
  while (std::getline(in, w, '_')) {
    if (w.size() == 2 && w[0] == 'c' && std::isdigit(static_cast<unsigned char>(w[1])))
      w = "configuration " + w.substr(1);
    words += (words.empty() ? "" : ", ") + w;
  }
  if (kind == "strip") return "Frames at equal time steps: " + words;
  if (kind == "locus") return "Stroboscopic locus: " + words;
  return words;
}

Section frames_section(const ResultsRecord& record) {
  Section s;
  s.id = "frames";
  s.heading = "Frames of the motion (MuJoCo replay)";
  Strip strip;
  for (const std::string& f : record.frames) {
    bool wide = false;
    strip.labels.push_back(frame_label(f, &wide));
    strip.files.push_back(f);
    strip.wide.push_back(wide);
  }
  if (strip.files.empty()) {
    s.paragraph("No frames were rendered for this case (run without --no-render to get them).");
  } else {
    strip.caption =
        "The solved motion replayed in the MuJoCo model of the arm and rendered "
        "off-screen (OSMesa): strips of frames in time order and stroboscopic loci "
        "of the whole motion.";
    s.strip(std::move(strip));
  }
  return s;
}

Section provenance_section(const ResultsRecord& record, const cases::CaseInfo& info) {
  Section s;
  s.id = "provenance";
  s.heading = "Provenance";
  s.new_page = false;
  Table t;
  t.header = {"item", "value"};
  t.rows.push_back({"armstudy version", record.armstudy_version});
  const std::string commit = record.git_commit.value_or("");
  t.rows.push_back({"git commit", commit.empty() ? "unknown" : commit});
  // the machine and libraries behind the numbers and frames
  const ProvenanceRecord& p = record.provenance;
  for (const auto& [k, v] :
       {std::pair<const char*, std::optional<std::string>>{"compiler", p.compiler},
        {"cpu_model", p.cpu_model},
        {"gl_renderer", p.gl_renderer},
        {"gl_version", p.gl_version},
        {"mesa_version", p.mesa_version},
        {"mujoco_version", p.mujoco_version}})
    if (v) t.rows.push_back({label_from_key(k), *v});
  t.rows.push_back({"case file", info.path});
  t.rows.push_back({"case sha256", info.sha256});
  t.rows.push_back({"machine-readable results", "results.json (in this folder)"});
  s.table(std::move(t));
  return s;
}

mus::data table_data(const Table& t) {
  mus::data d;
  d.set("caption", t.caption);
  d.set("has_caption", !t.caption.empty());
  d.set("narrow", t.narrow);
  mus::data header{mus::data::type::list};
  for (const auto& h : t.header) header << mus::data{"cell", h};
  d.set("header", header);
  mus::data rows{mus::data::type::list};
  for (size_t r = 0; r < t.rows.size(); ++r) {
    mus::data row;
    mus::data cells{mus::data::type::list};
    for (size_t c = 0; c < t.rows[r].size(); ++c) {
      mus::data cell;
      cell.set("cell", t.rows[r][c]);
      const std::string sw = (c == 0 && r < t.swatches.size()) ? t.swatches[r] : "";
      // swatch colours come from css_colour (#rrggbb) only; checked anyway
      const bool ok =
          sw.size() == 7 && sw[0] == '#' && std::all_of(sw.begin() + 1, sw.end(), [](char ch) {
            return std::isxdigit(static_cast<unsigned char>(ch));
          });
      cell.set("swatch", ok ? sw.substr(1) : "");
      cell.set("has_swatch", ok);
      cell.set("failed", t.rows[r][c] == "FAILED" || t.rows[r][c] == "BEYOND");
      // a column of case keys reads as code, not as labels
      cell.set("code", c < t.header.size() && (t.header[c] == "case key" || t.header[c] == "key"));
      cells << cell;
    }
    row.set("cells", cells);
    rows << row;
  }
  d.set("rows", rows);
  return d;
}

// one block of a section: a paragraph, note, code, table, figure, movies or a strip
mus::data block_data(const Block& b) {
  mus::data bd;
  switch (b.kind) {
    case Block::Kind::kParagraph: bd.set("paragraph", b.text); break;
    case Block::Kind::kNote: bd.set("note", b.text); break;
    case Block::Kind::kCode: bd.set("code", b.text); break;
    case Block::Kind::kTable: bd.set("table", table_data(b.table)); break;
    case Block::Kind::kFigure: {
      mus::data f;
      f.set("src", b.figure.file);
      f.set("caption", b.figure.caption);
      f.set("half", b.figure.half);
      bd.set("figure", f);
      break;
    }
    case Block::Kind::kMovies: {
      mus::data list{mus::data::type::list};
      for (const Movie& m : b.movies) {
        mus::data md;
        md.set("css_class", m.css_class);
        md.set("still", m.still);
        md.set("video", m.video);
        md.set("has_video", !m.video.empty());
        md.set("title", m.title);
        md.set("caption", m.caption);
        list << md;
      }
      mus::data mv;
      mv.set("list", list);
      bd.set("movies", mv);
      break;
    }
    case Block::Kind::kStrip: {
      mus::data st;
      st.set("caption", b.strip.caption);
      mus::data imgs{mus::data::type::list};
      for (size_t k = 0; k < b.strip.files.size(); ++k) {
        mus::data im;
        im.set("src", b.strip.files[k]);
        im.set("label", k < b.strip.labels.size() ? b.strip.labels[k] : "");
        im.set("wide", k < b.strip.wide.size() && b.strip.wide[k]);
        imgs << im;
      }
      st.set("images", imgs);
      bd.set("strip", st);
      break;
    }
  }
  return bd;
}

// the answer box on page 1
mus::data answer_data(const AnswerBox& a) {
  mus::data ad;
  ad.set("sentence", a.sentence);
  ad.set("has_picture", !a.picture.empty());
  ad.set("picture", a.picture);
  ad.set("picture_caption", a.picture_caption);
  ad.set("picture_is_frame", a.picture.ends_with(".png"));
  mus::data figs{mus::data::type::list};
  for (const auto& [k, v] : a.figures) {
    mus::data e;
    e.set("label", k);
    e.set("value", v);
    figs << e;
  }
  ad.set("figures", figs);
  ad.set("has_figures", !a.figures.empty());
  ad.set("verdict", a.verdict);
  ad.set("verdict_ok", a.verdict_ok);
  auto list = [](const std::vector<std::string>& v) {
    mus::data l{mus::data::type::list};
    for (const auto& s : v) l << mus::data{"text", s};
    return l;
  };
  ad.set("binding", list(a.binding));
  ad.set("has_binding", !a.binding.empty());
  ad.set("assumptions", list(a.assumptions));
  ad.set("has_assumptions", !a.assumptions.empty());
  ad.set("source", a.source);
  ad.set("has_source", !a.source.empty());
  ad.set("sensitivity_chart", a.sensitivity_chart);
  ad.set("sensitivity_caption", a.sensitivity_caption);
  ad.set("has_sensitivity", !a.sensitivity_chart.empty());
  return ad;
}

mus::data page_data(const CasePage& page, const cases::CaseInfo& info) {
  mus::data d;
  d.set("title", page.title);
  d.set("case_name", info.name);
  d.set("study", page.study);
  std::string study_words = page.study;
  std::replace(study_words.begin(), study_words.end(), '_', '-');
  d.set("study_words", study_words);
  d.set("status", page.status);
  d.set("solved", page.status_ok.value_or(page.status == "solved"));
  d.set("message", page.message);
  d.set("description", page.description);
  d.set("has_description", !page.description.empty());
  mus::data kf{mus::data::type::list};
  for (const auto& [k, v] : page.key_figures) {
    mus::data e;
    e.set("label", k);
    e.set("value", v);
    kf << e;
  }
  d.set("key_figures", kf);
  d.set("has_key_figures", !page.key_figures.empty());
  mus::data toc{mus::data::type::list};
  mus::data sections{mus::data::type::list};
  for (const auto& s : page.sections) {
    mus::data t;
    t.set("id", s.id);
    t.set("heading", s.heading);
    toc << t;
    mus::data sd;
    sd.set("id", s.id);
    sd.set("heading", s.heading);
    sd.set("new_page", s.new_page);
    mus::data blocks{mus::data::type::list};
    for (const auto& b : s.blocks) {
      blocks << block_data(b);
    }
    sd.set("blocks", blocks);
    sections << sd;
  }
  d.set("toc", toc);
  d.set("sections", sections);
  d.set("case_sha256", info.sha256);
  d.set("has_sha256", !info.sha256.empty());
  mus::data links{mus::data::type::list};
  for (size_t k = 0; k < page.links.size(); ++k) {
    mus::data l;
    l.set("label", page.links[k].first);
    l.set("href", page.links[k].second);
    l.set("first", k == 0);
    links << l;
  }
  d.set("links", links);
  d.set("has_links", !page.links.empty());
  d.set("data_link", "results.json");
  d.set("has_answer", page.answer.has_value());
  if (page.answer) d.set("answer", answer_data(*page.answer));
  return d;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> key_figures(const ResultsRecord& record) {
  // the study's own choice, results.json "key_figures": [{name, value, unit, label}]
  std::vector<std::pair<std::string, std::string>> out;
  for (const KeyFigureRecord& k : record.key_figures)
    out.emplace_back(k.label.empty() ? k.name : k.label,
                     format_sig(k.value, 5) + (k.unit.empty() ? "" : " " + k.unit));
  return out;
}

// (over 60 lines, kept whole: the page's parts in page order, then the atomic write)
void write_case_report(const fs::path& dir, const cases::CaseInfo& info,
                       const nlohmann::json& results, StudySections sections, StudyAnswer answer) {
  if (!sections) throw std::invalid_argument("study '" + info.study + "' has no report sections");
  const ResultsRecord record = read_record(results);
  CasePage page;
  page.title = info.name;
  page.study = info.study;
  page.status = record.status;
  page.message = record.message;
  page.description = info.description;
  page.key_figures = key_figures(record);

  FigureWriter figures(dir);
  const bool solved = record.solved();
  if (!solved) {
    Section s;
    s.id = "unsolved";
    s.heading = "Why the study has no answer";
    s.new_page = false;
    s.paragraph(page.message.empty() ? "The study could not be solved." : page.message);
    page.sections.push_back(std::move(s));
  }
  sections(results, record, figures, page);  // the study's own (its registry record)
  if (record.sensitivity) page.sections.push_back(sensitivity_section(*record.sensitivity));
  // page 2 opens with the source beside armstudy, for a case that reproduces one
  if (record.source) page.sections.insert(page.sections.begin(), source_section(*record.source));
  if (solved) {
    Section motion = animation_section(record.animations);
    if (!motion.blocks.empty()) page.sections.push_back(std::move(motion));
    Section frames = frames_section(record);
    // a strip another section shows already (MuJoCo's replay of the plan) is not repeated,
    // nor the plain strip of a motion whose replay strip (the same frames with MuJoCo's
    // simulated skeleton drawn over the arm) is shown
    std::set<std::string> shown;
    const std::string kReplay = "_planned-and-simulated_strip.png";
    for (const Section& other : page.sections)
      for (const Block& ob : other.blocks)
        if (ob.kind == Block::Kind::kStrip)
          for (const std::string& f : ob.strip.files) {
            shown.insert(f);
            if (f.ends_with(kReplay))
              shown.insert(f.substr(0, f.size() - kReplay.size()) + "_strip.png");
          }
    for (Block& b : frames.blocks) {
      if (b.kind != Block::Kind::kStrip) continue;
      Strip kept = b.strip;
      kept.files.clear(), kept.labels.clear(), kept.wide.clear();
      for (size_t k = 0; k < b.strip.files.size(); ++k)
        if (!shown.count(b.strip.files[k])) {
          kept.files.push_back(b.strip.files[k]);
          kept.labels.push_back(b.strip.labels[k]);
          kept.wide.push_back(b.strip.wide[k]);
        }
      if (kept.files.size() < b.strip.files.size())
        kept.caption +=
            " The strips of frames at equal time steps are in the MuJoCo dynamic "
            "replay above, with MuJoCo's simulated motion drawn over them.";
      b.strip = std::move(kept);
    }
    page.sections.push_back(std::move(frames));
  }
  page.sections.push_back(checks_section(record));
  // the appendix: the case as written and where the numbers come from
  page.sections.push_back(case_section(info));
  page.sections.push_back(provenance_section(record, info));
  lay_out_case_page(results, answer, page);
  if (record.sensitivity && page.answer)
    page.answer->sensitivity_chart =
        write_tornado(dir, *record.sensitivity, &page.answer->sensitivity_caption);

  if (record.case_info.expect == page.status) page.status += " (as the case expects)";
  // an answer its study calls not converged is no plain optimum: the badge says so
  if (page.answer && !page.answer->status_note.empty()) {
    page.status += ", " + page.answer->status_note;
    page.status_ok = false;
  }
  write_page(dir, page, info);
  // the animations' rules after the shared stylesheet (the page's CSP allows no inline style)
  if (const std::string css = animation_css(record.animations); !css.empty())
    write_text(dir / "report.css",
               read_text(dir / "report.css") + "\n/* animations, generated */\n" + css);
}

void write_page(const fs::path& dir, const CasePage& page, const cases::CaseInfo& info,
                const std::string& data_link, const std::string& file_name) {
  copy_stylesheet(dir);
  mus::data d = page_data(page, info);
  if (!data_link.empty()) d.set("data_link", data_link);
  write_text(dir / file_name, render_template("case.html", d));
}

namespace {

// one row of the index page: a case folder's results.json, read and typed
struct IndexRow {
  std::string name;
  nlohmann::json results;
  std::optional<ResultsRecord> record;  ///< empty: unreadable
  AnswerBox answer;
};

// the rows of every case folder in out_dir that holds a results.json
std::vector<IndexRow> read_index_rows(const fs::path& out_dir,
                                      const std::vector<IndexStudy>& studies) {
  auto study_of = [&](const std::string& name) -> const IndexStudy* {
    for (const IndexStudy& st : studies)
      if (st.study == name) return &st;
    return nullptr;
  };
  std::vector<IndexRow> rows;
  if (fs::is_directory(out_dir))
    for (const auto& e : fs::directory_iterator(out_dir)) {
      const std::string name = e.path().filename().string();
      if (!e.is_directory() || name.empty() || name[0] == '.') continue;
      const fs::path rj = e.path() / "results.json";
      std::error_code ec;
      const fs::file_status st = fs::symlink_status(rj, ec);
      if (!fs::exists(st)) continue;
      IndexRow row{name, {}, {}, {}};
      // another folder's results.json is read only when it is a regular file of at most
      // kMaxIndexedResultsBytes: a FIFO, device or link is an unreadable row, never opened
      const bool readable = st.type() == fs::file_type::regular &&
                            fs::file_size(rj, ec) <= kMaxIndexedResultsBytes && !ec;
      try {
        if (!readable) throw ResultsError(rj.string(), "not a regular file of armstudy's");
        row.results = nlohmann::json::parse(read_text(rj));
        row.record = read_record(row.results);  // every shared key, typed (else: unreadable)
        const IndexStudy* study = study_of(row.record->study);
        row.answer = answer_box(row.results, CasePage{}, study ? study->answer : nullptr);
      } catch (const nlohmann::json::exception&) {
        row.record.reset();
      } catch (const ResultsError&) {
        row.record.reset();
      }
      if (!row.record) row.answer = AnswerBox{};
      rows.push_back(std::move(row));
    }
  return rows;
}

// failed: not solved when the case expects it, or a check failed (or unreadable)
bool row_failed(const IndexRow& r) {
  if (!r.record) return true;
  return r.record->status != r.record->expected_status() || !r.record->checks_passed();
}

// a case's line on the index page: status, answer, verdict, key figures, thumbnail, links
mus::data index_row_data(const IndexRow& r, const fs::path& out_dir) {
  mus::data e;
  e.set("name", r.name);
  const std::string status = r.record ? r.record->status : "unreadable results.json";
  const bool expected = r.record && r.record->case_info.expect == status;
  e.set("study", r.record ? r.record->study : "");
  e.set("status", expected ? status + " (as the case expects)" : status);
  e.set("solved", status == "solved");
  // the answer in one line: the message up to its first ';' (the case page has it all)
  const std::string message = r.record ? r.record->message : "";
  e.set("message", message.substr(0, message.find("; ")));
  e.set("failed", row_failed(r));
  // the check verdict and the key picture of the case's answer box
  const AnswerBox& answer = r.answer;
  e.set("verdict", r.record ? answer.verdict : "The study ran no checks on this case.");
  e.set("verdict_ok", answer.verdict_ok);
  // the first few key figures; the case page has them all
  constexpr size_t kIndexFigures = 4;
  mus::data kf{mus::data::type::list};
  const auto figures =
      r.record ? key_figures(*r.record) : std::vector<std::pair<std::string, std::string>>{};
  for (size_t k = 0; k < figures.size() && k < kIndexFigures; ++k) {
    mus::data x;
    x.set("label", figures[k].first);
    x.set("value", figures[k].second);
    kf << x;
  }
  e.set("key_figures", kf);
  e.set("more_figures", figures.size() > kIndexFigures
                            ? "and " + std::to_string(figures.size() - kIndexFigures) + " more"
                            : "");
  e.set("has_more_figures", figures.size() > kIndexFigures);
  // thumbnail: the answer's key picture, else the first figure of the page
  std::string thumb = answer.picture;
  if (thumb.empty()) {
    std::vector<std::string> svgs;
    for (const auto& f : fs::directory_iterator(out_dir / r.name))
      if (f.path().extension() == ".svg") svgs.push_back(f.path().filename().string());
    std::sort(svgs.begin(), svgs.end());
    if (!svgs.empty()) thumb = svgs.front();
  }
  const bool has_thumb = !thumb.empty() && fs::exists(out_dir / r.name / thumb);
  e.set("has_thumb", has_thumb);
  e.set("thumb", has_thumb ? r.name + "/" + thumb : "");
  e.set("has_report", fs::exists(out_dir / r.name / "index.html"));
  e.set("has_pdf", fs::exists(out_dir / r.name / "report.pdf"));
  return e;
}

// each study's figure over all of its cases (e.g. the thesis's figure 9.30 over the
// placement cases), drawn here where every case is
mus::data figures_across_cases(const fs::path& out_dir, const std::vector<IndexStudy>& studies,
                               const std::vector<IndexRow>& rows) {
  mus::data across{mus::data::type::list};
  for (const IndexStudy& st : studies) {
    if (!st.figure.draw) continue;
    std::vector<std::pair<std::string, const nlohmann::json*>> cases;
    for (const auto& r : rows)
      if (r.record && r.record->study == st.study) cases.emplace_back(r.name, &r.results);
    const fs::path svg = out_dir / std::string(st.figure.file);
    if (!st.figure.draw(cases, svg)) {
      fs::remove(svg);
      continue;
    }
    mus::data f;
    f.set("file", std::string(st.figure.file));
    f.set("heading", std::string(st.figure.heading));
    f.set("alt", std::string(st.figure.alt));
    f.set("caption", std::string(st.figure.caption));
    across << f;
  }
  return across;
}

}  // namespace

int write_index(const fs::path& out_dir, const std::vector<IndexStudy>& studies) {
  std::vector<IndexRow> rows = read_index_rows(out_dir, studies);
  // failures first, then by name
  std::sort(rows.begin(), rows.end(), [&](const IndexRow& a, const IndexRow& b) {
    const bool fa = row_failed(a), fb = row_failed(b);
    return fa != fb ? fa : a.name < b.name;
  });
  mus::data d;
  mus::data list{mus::data::type::list};
  for (const auto& r : rows) list << index_row_data(r, out_dir);
  d.set("cases", list);
  d.set("count", std::to_string(rows.size()));
  d.set("has_sweep", fs::exists(out_dir / "sweep" / "index.html"));
  fs::create_directories(out_dir);
  // never over a file of these names that armstudy did not write (report/owned_output.hpp)
  check_run_level_output(out_dir, "index.html");
  check_run_level_output(out_dir, "report.css");
  for (const IndexStudy& st : studies)
    if (st.figure.draw) check_run_level_output(out_dir, std::string(st.figure.file));
  d.set("across_cases", figures_across_cases(out_dir, studies, rows));
  copy_stylesheet(out_dir);
  write_text(out_dir / "index.html", render_template("index.html", d));
  return static_cast<int>(rows.size());
}

}  // namespace armstudy::report
