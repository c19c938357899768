// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What a case's source printed, to set beside armstudy's numbers (`source:` in YAML): the
/// figures the source prints for the case and the claims it makes about it, each with
/// where it is printed and the results.json values that correspond to it. The report's
/// "Source and armstudy" part (report/source_comparison.hpp) compares them; the numbers
/// are data of the case file, never constants of the code.
///
///   source:
///     document: Kopmaz (2016)
///     printed:
///       - where: "Ch. 9, example 3, p. 31"
///         says: "min(EC1) = 9.58 J (cycloidal program)"
///         value: 9.58                  # a figure; its printed digits give its precision
///         unit: J
///         at_source_setting:
///         placement.evaluations[label=thesis-config-1,program=cycloidal].energy_J at_optimum:
///         "key:energy_J[cycloidal,1]" reason: kopmaz-energies      # the docs/defects.md entry
///         that explains a difference why: "the thesis's energies follow from none of its own
///         parameters"
///       - where: "Ch. 9, example 3, p. 31"
///         says: "the second configuration needs less energy"
///         claim: {a: "key:energy_J[cycloidal,2]", relation: less, b: "key:energy_J[cycloidal,1]"}
///
/// A value path is dotted keys of results.json, `[N]` an index and `[k=v,...]` the one
/// element of an array whose keys have those values; `key:NAME` is the value of the key
/// figure NAME. A claim compares two values (`b` may be a number), each with its error where
/// the case names one (`a_error`, `b_error`):
///
///       - says: "both programs share one optimum"
///         claim:
///           a: placement.optima[program=poly345,configuration=1].root_xy_m
///           relation: same
///           b: placement.optima[program=cycloidal,configuration=1].root_xy_m
///           a_error: placement.optima[program=poly345,configuration=1].refinement.root_error_m
///           b_error: placement.optima[program=cycloidal,configuration=1].refinement.root_error_m

#include <optional>
#include <string>
#include <vector>

namespace armstudy::cases {

class Map;

/// A claim of the source: value a stands in `relation` to value b. A value path may lead to
/// a list of numbers (a point, e.g. root_xy_m): then a and b are compared by their distance,
/// and only `same` applies.
struct SourceClaim {
  std::string a;          ///< value path
  std::string relation;   ///< "less", "greater" or "same"
  std::string b;          ///< value path, or a number as text
  double tie_rel = 1e-6;  ///< |a - b| <= tie_rel max(|a|, |b|) is a tie, not a relation
  std::string measure;    ///< what a and b are, in words (e.g. "energy, J")
  /// the resolution of the methods a and b come from, relative: |a - b| within it (and
  /// above tie_rel) decides nothing, the verdict "tie" (0: none given)
  double resolution_rel = 0;
  /// value paths (or numbers as text) of the absolute errors of a and b (empty: none): the
  /// values decide nothing within their sum. `same` holds when |a - b| (or the points'
  /// distance) is within it; `less` and `greater` are a tie within it
  std::string a_error = {}, b_error = {};
};

/// One printed figure or claim of the source.
struct PrintedItem {
  std::string where;                 ///< chapter, example, page, table or equation of the source
  std::string says;                  ///< what the source prints, as it prints it
  std::optional<double> value;       ///< a figure: the printed number
  std::string unit;                  ///< its unit ("" for none)
  double tolerance = 0;              ///< half a unit of the last printed digit, or given
  bool by_constraint = false;        ///< the tolerance is a constraint of the study itself
  std::string at_source_setting;     ///< armstudy's value under the source's own setting
  std::string at_optimum;            ///< armstudy's value at its own optimum
  std::optional<SourceClaim> claim;  ///< a claim instead of a figure
  std::string reason;                ///< docs/defects.md anchor explaining a difference
  std::string why;                   ///< the reason in one sentence
};

/// The case's `source:` part.
struct SourceSpec {
  std::string document;              ///< e.g. "Kopmaz (2016)"; empty: the case reproduces no source
  std::vector<PrintedItem> printed;  ///< each item's `why` filled in from `reasons`
  bool empty() const { return printed.empty(); }
};

/// Reads `source:` from the case's root mapping (nothing when absent); errors go to the
/// map's diagnostics with their line.
SourceSpec read_source(Map& root);

/// Half a unit of the last digit of a number as written: "9.58" -> 0.005, "17" -> 0.5,
/// "1.2e-3" -> 0.00005.
double printed_precision(const std::string& text);

}  // namespace armstudy::cases
