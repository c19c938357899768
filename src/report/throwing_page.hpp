// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// The throwing page's types and helpers shared by report/throwing_section.cpp (method,
// results, seeds, motors, contact) and report/throwing_flight.cpp (the ball, release and
// flight; the optimisers' convergence).

#include <string>
#include <vector>

#include "report/study_sections.hpp"
#include "studies/throwing/study_results.hpp"

namespace armstudy::report::throwing_page {

using TS = studies::ThrowingStudyResults;

/// A motion drawn: its label, its colour's key and its typed record.
struct Motion {
  std::string label, colour_key;
  const TS::Motion* m;
};

// what every part of the page reads: the typed results, the optimisers' part (empty when
// the study stopped before them: nothing of it is drawn) and the motions drawn
struct Page {
  const TS& section;
  const TS::Optimised& th;
  bool ran;
  std::vector<Motion> ms;
};

/// One plot over time per motion: a scalar series, or column `col` of a series of rows (every
/// column when col < 0, named by column_names).
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, std::vector<double> TS::Series::*scalar,
                     TS::Rows TS::Series::*rows, int col,
                     const std::vector<std::string>& column_names);
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, TS::Rows TS::Series::*rows, int col,
                     const std::vector<std::string>& column_names);
LinePlot motion_plot(const std::vector<Motion>& ms, const std::string& title,
                     const std::string& y_label, std::vector<double> TS::Series::*scalar);

/// The ball in the tray, release and flight.
Section ball_section(const Page& p, FigureWriter& figures);

/// Both optimisers' convergence and the simulation's accuracy.
Section convergence_section(const Page& p, FigureWriter& figures);

}  // namespace armstudy::report::throwing_page
