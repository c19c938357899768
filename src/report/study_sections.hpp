#pragma once
/// Per-study parts of a case page: each reads its study's section of results.json into the
/// study's typed result (report::read_section, studies/<study>/results_section.hpp; a
/// section that is not the study's is a ResultsError naming the key) and adds sections
/// (method, results tables, plots, notes on the source document) to the page. A value that
/// is null in the file (not finite) is shown as "n/a", never invented.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/page.hpp"

namespace armstudy::report {

/// results[study] of a placement case -> sections. @throws what the plot writers throw.
void placement_sections(const nlohmann::json& results, FigureWriter& figures, CasePage& page);
/// results[study] of a pendulum case -> sections.
void pendulum_sections(const nlohmann::json& results, FigureWriter& figures, CasePage& page);
/// results[study] of a throwing case -> sections.
void throwing_sections(const nlohmann::json& results, FigureWriter& figures, CasePage& page);
/// results[study] of a time-optimal case -> sections.
void time_optimal_sections(const nlohmann::json& results, FigureWriter& figures, CasePage& page);
/// Any study section: its scalar results as a table and every time series found (an object
/// with a "t_s" array) as plots. Used for studies without their own builder and for the
/// parts of a section a builder does not know.
void generic_sections(const nlohmann::json& section, FigureWriter& figures, CasePage& page);

/// Plots of every time series below `node` (objects holding a "t_s" array): one plot per
/// quantity, the series of different owners (optimum, solver, ...) overlaid in their
/// colours. Keys in `skip` are not plotted. Returns the number of figures added.
int time_series_figures(const nlohmann::json& node, const std::string& what, FigureWriter& figures,
                        Section& section, const std::vector<std::string>& skip = {});

/// The optimal root locations of several placement cases in one plot (the thesis's
/// Figure 9.30): per program and configuration, the locus of its optimum as the line length
/// changes from case to case. `cases` holds (case name, results.json). Writes `svg` and
/// returns true when at least two placement cases have an optimum; false (nothing written)
/// otherwise.
bool placement_loci_across_cases(
    const std::vector<std::pair<std::string, const nlohmann::json*>>& cases,
    const std::filesystem::path& svg);

/// A named holder of a time series (an optimum, a solver, a motion) and its colour key.
struct Owner {
  std::string label;       ///< legend text, e.g. "cycloidal, configuration 1"
  std::string colour_key;  ///< for colour_for, e.g. "cycloidal/1"
  const nlohmann::json* series = nullptr;  ///< object with "t_s" and the keys plotted
};

/// One line plot over time of `keys` of every owner: colour per owner, line style per key
/// (solid, dashed, dotted: joint 1, 2, 3), legend "<owner>, <key label>". Keys that hold
/// one array per sample ([[j1, j2], ...]) contribute one curve per column, named by
/// `key_labels` (one per key, or one per column of a single key).
LinePlot owners_plot(const std::string& title, const std::string& y_label,
                     const std::vector<Owner>& owners, const std::vector<std::string>& keys,
                     const std::vector<std::string>& key_labels);

/// A key/value table of a json object, nested keys joined with '.', arrays of numbers
/// written as [a, b]; arrays of strings (e.g. "choices") are left out.
Table json_table(const nlohmann::json& obj, std::string caption);

/// Axis label of a results.json key by its unit suffix: "energy_J" -> "energy (J)",
/// "q_rad" -> "q (rad)", "phi_deg" -> "phi (deg)".
std::string label_from_key(const std::string& key);

}  // namespace armstudy::report
