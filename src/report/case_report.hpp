// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The study report of one case (DIR/<case>/index.html with its figures and stylesheet),
/// the page of all cases (DIR/index.html) and the PDF print through headless Chromium.

#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/case_info.hpp"
#include "report/answer_box.hpp"
#include "report/templates.hpp"  // template_dir, check_templates

namespace armstudy::report {

struct CasePage;
class FigureWriter;
struct ResultsRecord;

/// A study's own sections of its page, from the whole results.json (its registry record,
/// app::StudyEntry::report; report/study_sections.hpp; app::study_parts reads the typed
/// section once and hands it to the study's function, with the shared record the page writer
/// has read already).
using StudySections = std::function<void(const nlohmann::json& results, const ResultsRecord& record,
                                         FigureWriter& figures, CasePage& page)>;

/// Writes the report of one case into `dir` (the case folder, which already holds
/// results.json and the frames listed in results["frames"]): index.html, report.css and
/// one SVG per plot. `results` is the case's results.json: the shared record
/// (report/results_record.hpp) and the study's own section under results[info.study];
/// `sections` adds the study's own sections (required) and `answer` its lines of the answer
/// box (none when null). Reads the templates from template_dir().
/// @throws std::runtime_error when a template is missing or a file cannot be written;
/// std::invalid_argument when a plot cannot be drawn from the data or `sections` is null;
/// ResultsError (report/results_fields.hpp) naming the first key that does not read.
void write_case_report(const std::filesystem::path& dir, const cases::CaseInfo& info,
                       const nlohmann::json& results, StudySections sections, StudyAnswer answer);

/// Writes `page` as `dir`/`file_name` (with report.css) through the case template; the
/// header links to `data_link` (default: the case's results.json) unless page.links is set.
/// @throws std::runtime_error when a template is missing or a file cannot be written.
void write_page(const std::filesystem::path& dir, const CasePage& page, const cases::CaseInfo& info,
                const std::string& data_link = "", const std::string& file_name = "index.html");

/// A figure the index page draws over every case of one study (its registry record,
/// app::StudyEntry::index_figure), e.g. the placement optima's root loci across the cases.
struct IndexFigure {
  std::string_view file;     ///< the SVG in out_dir, e.g. "placement_root_loci.svg"
  std::string_view heading;  ///< of its section on the index page
  std::string_view alt;      ///< the image's alternative text
  std::string_view caption;
  /// Draws `svg` from (case name, results.json) of the study's readable cases; false when
  /// there are too few to draw (nothing written). Null: the study has no such figure.
  bool (*draw)(const std::vector<std::pair<std::string, const nlohmann::json*>>& cases,
               const std::filesystem::path& svg) = nullptr;
};

/// What the index page needs of a study's registry record.
struct IndexStudy {
  std::string_view study;
  StudyAnswer answer = nullptr;  ///< its lines of the answer box (the thumbnail among them)
  IndexFigure figure;            ///< its figure over all its cases, if any
};

/// Writes `out_dir`/index.html (and its report.css): one row per case folder in out_dir that
/// holds a results.json (folders starting with '.' are skipped), failures first, then by
/// name, with the study, status, key figures, a thumbnail (the answer box's key picture,
/// else the first figure) and a link to the case's report; then each study's figure over
/// its cases (`studies`, from the registry). A results.json that does not read
/// (read_record) is listed as unreadable. Returns the number of cases listed.
/// @throws std::runtime_error when out_dir/index.html cannot be written.
int write_index(const std::filesystem::path& out_dir, const std::vector<IndexStudy>& studies);

/// Key figures of a case for the index and the page header (label, value with unit).
std::vector<std::pair<std::string, std::string>> key_figures(const ResultsRecord& record);

/// Chromium could not be found or did not print.
class PdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The Chromium executable: $ARMSTUDY_CHROMIUM if set, else the first of
/// chromium-headless-shell, chromium, chromium-browser, google-chrome on PATH; empty when
/// none is found.
std::string find_chromium();

/// Why --pdf cannot print when find_chromium() finds nothing: where it looked and what to
/// install.
std::string missing_chromium_text();

/// Prints `html` (a local file) to `pdf` with headless Chromium (A4 from the page's print
/// CSS, no header or footer, a fresh profile, no network services) over the DevTools
/// protocol, with scripts off and every request outside `html`'s folder refused (a
/// `file://` iframe of another file prints as an error, not as that file's text), writing
/// through a temporary file. Gives up after `timeout_s` seconds.
/// @throws PdfError naming the problem (Chromium missing: how to install it).
void print_pdf(const std::filesystem::path& html, const std::filesystem::path& pdf,
               double timeout_s = 120);

/// One page to print: its HTML and the PDF to write.
struct PdfJob {
  std::filesystem::path html;
  std::filesystem::path pdf;
};

/// Prints every page of `jobs` as print_pdf does, through ONE headless Chromium for all of
/// them (DevTools protocol over --remote-debugging-pipe, Page.printToPDF with the options of
/// --print-to-pdf: backgrounds, CSS page size, no header or footer), up to `parallel` pages
/// at a time in their own tabs; each PDF written through a temporary file. A page that does
/// not print within `timeout_s` s of its start fails alone. If the browser dies (or does
/// not speak the protocol), the pages it has not printed go through print_pdf one by one,
/// each with a browser of its own.
/// Returns one message per job: empty when printed, else why not.
/// @throws PdfError when Chromium is missing.
std::vector<std::string> print_pdfs(const std::vector<PdfJob>& jobs, int parallel,
                                    double timeout_s = 120);

/// Prints pages while a run goes on: each page given to add() is printed, as print_pdfs
/// does, by one headless Chromium on a thread of its own (started with the first page),
/// `parallel` at a time; `done` is called on that thread with "" or why the page was not
/// printed. finish() (also the destructor) waits for every page added.
/// @throws PdfError when Chromium is missing.
class PdfPrinter {
 public:
  explicit PdfPrinter(int parallel, double timeout_s = 120);
  ~PdfPrinter();
  PdfPrinter(const PdfPrinter&) = delete;
  PdfPrinter& operator=(const PdfPrinter&) = delete;
  void add(PdfJob job, std::function<void(const std::string& error)> done);
  void finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Kills the process group of every browser printing now and removes their profiles (the
/// clean-up of a signal; the prints then fail).
void kill_browsers();

/// Removes the Chromium profiles (`armstudy-chromium-*` in the system's temporary folder)
/// that no printing process holds locked: what killed runs left. Returns how many.
size_t remove_stale_profiles();

}  // namespace armstudy::report
