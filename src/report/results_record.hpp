// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The parts of results.json every study shares, typed: the record around the study's own
/// section (results[study], studies/<study>/study_results.hpp). `run_case` writes it from
/// this record, the report, the index page and `armstudy merge` read it back with
/// read_record(): every key required unless optional, an unknown or misspelt key an error
/// naming its JSON pointer. results.schema.json holds its schema (report/results_fields.hpp
/// turns the `fields` below into the writer, the reader and the schema).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/results_fields.hpp"
#include "report/sensitivity_record.hpp"

namespace armstudy::report {

/// The version of results.json this armstudy writes and reads (no other is read). It
/// changes when a key is removed or renamed or changes meaning.
inline constexpr int kSchemaVersion = 2;

/// results["case"]: the case file that was run.
struct CaseRecord {
  struct Sweep {
    std::string name;
    std::map<std::string, std::string> point;  ///< case key path -> its value as YAML text
  };
  std::string name, path, sha256;
  std::optional<std::string> description, expect;
  std::optional<Sweep> sweep;
  /// every value the case file writes by its key path, as YAML text (cases/case_inputs.hpp)
  std::optional<std::map<std::string, std::string>> inputs;
};

/// results["provenance"]: what produced the numbers and frames.
struct ProvenanceRecord {
  std::string armstudy_version;
  std::optional<std::string> git_commit;
  std::string mujoco_version, compiler, cpu_model;
  std::optional<std::string> gl_renderer, gl_version, mesa_version;  ///< when frames were rendered
};

/// One of results["checks"]: a check the study ran on its own answer.
struct CheckRecord {
  std::string name, description;
  double value = 0, tolerance = 0;
  bool passed = false;
};

/// One of results["key_figures"]: a number a reader compares across cases.
struct KeyFigureRecord {
  std::string name;
  double value = 0;
  std::string unit, label;
};

/// results["run_options"]: the options of the run that change its output.
struct RunOptionsRecord {
  bool render = false;
};

/// One of results["exports"]: a file for other tools.
struct ExportRecord {
  std::string file, kind, what, motion;
  std::optional<std::vector<double>> keyframe_times_s;  ///< kind "mjcf"
  std::optional<long long> rows;                        ///< kind "motion_csv"
  std::optional<std::vector<std::string>> columns;      ///< kind "motion_csv"
};

/// One of results["animations"]: a rendered motion as a sprite sheet, a still and a video.
struct AnimationRecord {
  std::string name, title, sprite, still;
  std::optional<std::string> video;  ///< null when ffmpeg is missing
  int frames = 0, columns = 0, frame_width_px = 0, frame_height_px = 0;
  double fps = 0, duration_s = 0, video_duration_s = 0;
  std::optional<std::string> note;
};

/// One of results["files"]: a file written beside results.json.
struct FileRecord {
  std::string path;
  long long bytes = 0;
  std::string sha256;
};

/// One of results["source"]["rows"]: a figure or claim the case's source printed, beside
/// armstudy's value (report/source_comparison.hpp).
struct SourceRowRecord {
  std::string where, says;
  std::string kind;               ///< "figure" or "claim"
  std::optional<double> printed;  ///< a figure: the printed number
  std::string unit;
  std::optional<double> tolerance;          ///< a figure: half a unit of its last printed digit
  std::optional<double> at_source_setting;  ///< armstudy under the source's own setting
  std::optional<double> at_optimum;         ///< armstudy at its own optimum
  std::optional<double> difference;         ///< armstudy (source setting, else optimum) - printed
  std::optional<double> a, b;               ///< a claim: the two values it compares
  std::optional<std::vector<double>> a_point, b_point;  ///< a claim about points, instead
  std::optional<double> distance;                       ///< a claim about points: |a - b|
  std::optional<double> a_error, b_error;  ///< a claim: the errors of a and b, where given
  std::optional<std::string> relation;     ///< a claim: "less", "greater" or "same"
  std::string
      verdict;  ///< agrees, differs, met_by_constraint, confirmed, contradicted, tie or no_value
  std::optional<std::string> reason;  ///< docs/defects.md anchor
  std::string why;
};

/// results["source"]: the case's source beside armstudy (cases with `source:` only).
struct SourceRecord {
  std::string document;
  std::vector<SourceRowRecord> rows;
};

/// The whole of results.json but the study's own section (results[study]).
struct ResultsRecord {
  int schema_version = kSchemaVersion;
  std::string armstudy_version;
  std::optional<std::string> git_commit;
  std::string study;
  CaseRecord case_info;
  ProvenanceRecord provenance;
  std::string status;  ///< "solved" or "unsolvable"
  std::string message;
  std::optional<double> run_time_s;  ///< wall clock from the case's start to its results.json
  std::vector<CheckRecord> checks;
  std::vector<KeyFigureRecord> key_figures;
  RunOptionsRecord run_options;
  std::vector<std::string> frames;
  std::vector<ExportRecord> exports;
  std::vector<AnimationRecord> animations;
  std::vector<FileRecord> files;
  std::optional<SourceRecord> source;
  std::optional<SensitivityRecord> sensitivity;

  bool solved() const { return status == "solved"; }
  /// the status the case expects: "unsolvable" when its file says so, else "solved"
  std::string expected_status() const { return case_info.expect.value_or("solved"); }
  /// every check passed
  bool checks_passed() const {
    for (const CheckRecord& c : checks)
      if (!c.passed) return false;
    return true;
  }
};

inline const nlohmann::json kSha256 = {{"pattern", "^[0-9a-f]{64}$"}};

template <class V>
void fields(V& v, CaseRecord::Sweep& x) {
  v("name", x.name, "the sweep's name");
  v("point", x.point, "the swept case keys (dotted paths) and their values as YAML text");
}
template <class V>
void fields(V& v, CaseRecord& x) {
  v("name", x.name, "the case's name (its folder)",
    {{"pattern", "^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$"}});
  v("path", x.path, "the case file as given", {{"minLength", 1}});
  v("sha256", x.sha256, "SHA-256 of the case file", kSha256);
  v.optional("description", x.description, "the case's description");
  v.optional("expect", x.expect, "'unsolvable' when the case expects no answer",
             {{"enum", nlohmann::json::array({"unsolvable"})}});
  v.optional("sweep", x.sweep, "the sweep and point this case was generated from");
  v.optional("inputs", x.inputs,
             "every value the case file writes, by its dotted key path (arm.links[1].length), "
             "as YAML text; armstudy diff lists those that differ between two runs");
}
template <class V>
void fields(V& v, ProvenanceRecord& x) {
  v("armstudy_version", x.armstudy_version, "armstudy's version");
  v.optional("git_commit", x.git_commit, "the commit armstudy was built from");
  v("mujoco_version", x.mujoco_version, "MuJoCo's version");
  v("compiler", x.compiler, "the compiler that built armstudy");
  v("cpu_model", x.cpu_model, "the machine's CPU");
  v.optional("gl_renderer", x.gl_renderer, "the OpenGL renderer of the frames");
  v.optional("gl_version", x.gl_version, "the OpenGL version of the frames");
  v.optional("mesa_version", x.mesa_version, "the Mesa version of the frames");
}
template <class V>
void fields(V& v, CheckRecord& x) {
  v("name", x.name, "stable identifier, dotted", {{"pattern", "^[a-z0-9_.]+$"}});
  v("description", x.description, "what it verifies");
  v("value", x.value, "the measured value (null: not finite)");
  v("tolerance", x.tolerance, "the largest value that passes");
  v("passed", x.passed, "value within tolerance");
}
template <class V>
void fields(V& v, KeyFigureRecord& x) {
  v("name", x.name, "stable identifier, e.g. min_energy_J", {{"minLength", 1}});
  v("value", x.value, "the figure (null: not finite)");
  v("unit", x.unit, "its unit, empty for none");
  v("label", x.label, "what a reader sees, in words (name is the stable id)");
}
template <class V>
void fields(V& v, RunOptionsRecord& x) {
  v("render", x.render, "frames were rendered (false with --no-render)");
}
template <class V>
void fields(V& v, ExportRecord& x) {
  v("file", x.file, "the file, beside results.json", {{"minLength", 1}});
  v("kind", x.kind, "what kind of file", {{"enum", nlohmann::json::array({"mjcf", "motion_csv"})}});
  v("what", x.what, "what it holds, in words");
  v("motion", x.motion, "which motion");
  v.optional("keyframe_times_s", x.keyframe_times_s, "kind mjcf: the time of each keyframe");
  v.optional("rows", x.rows, "kind motion_csv: rows below the header", {{"minimum", 0}});
  v.optional("columns", x.columns, "kind motion_csv: the header, each with its unit");
}
template <class V>
void fields(V& v, AnimationRecord& x) {
  v("name", x.name, "stem of its files");
  v("title", x.title, "which motion, in words");
  v("sprite", x.sprite, "the frames in a grid, left to right, top to bottom",
    {{"pattern", "\\.png$"}});
  v("still", x.still, "the last frame (the print and no-motion view)", {{"pattern", "\\.png$"}});
  v("video", x.video, "H.264 MP4 at real speed (null when ffmpeg is missing)");
  v("frames", x.frames, "frames of the animation", {{"minimum", 2}});
  v("columns", x.columns, "columns of the sprite grid", {{"minimum", 1}});
  v("frame_width_px", x.frame_width_px, "width of one sprite frame");
  v("frame_height_px", x.frame_height_px, "height of one sprite frame");
  v("fps", x.fps, "frames per second of real time (frame k at t0 + k / fps)");
  v("duration_s", x.duration_s, "duration of the motion");
  v("video_duration_s", x.video_duration_s, "frames / fps");
  v.optional("note", x.note, "why a part is missing");
}
template <class V>
void fields(V& v, FileRecord& x) {
  v("path", x.path, "relative to the case folder", {{"minLength", 1}});
  v("bytes", x.bytes, "its size", {{"minimum", 0}});
  v("sha256", x.sha256, "SHA-256 of its bytes", kSha256);
}
template <class V>
void fields(V& v, SourceRowRecord& x) {
  v("where", x.where, "where the source prints it (chapter, page, table, equation)");
  v("says", x.says, "what the source prints, as it prints it");
  v("kind", x.kind, "a printed number or a claim",
    {{"enum", nlohmann::json::array({"figure", "claim"})}});
  v.optional("printed", x.printed, "a figure: the printed number");
  v("unit", x.unit, "its unit, empty for none");
  v.optional("tolerance", x.tolerance,
             "a figure: half a unit of its last printed digit (or the case's tolerance)");
  v.optional("at_source_setting", x.at_source_setting,
             "armstudy's value under the source's own setting (null: none computed)");
  v.optional("at_optimum", x.at_optimum, "armstudy's value at its own optimum (null: none)");
  v.optional("difference", x.difference,
             "a figure: armstudy (at the source's setting, else at its optimum) minus printed");
  v.optional("a", x.a, "a claim: armstudy's value of its first term");
  v.optional("b", x.b, "a claim: armstudy's value of its second term");
  v.optional("a_point", x.a_point, "a claim about points: armstudy's point of its first term");
  v.optional("b_point", x.b_point, "a claim about points: armstudy's point of its second term");
  v.optional("distance", x.distance, "a claim about points: the distance between a and b");
  v.optional("a_error", x.a_error, "a claim: the absolute error of a (or of its point)");
  v.optional("b_error", x.b_error, "a claim: the absolute error of b (or of its point)");
  v.optional("relation", x.relation,
             "a claim: what the source says a is to b (same: equal within their errors)",
             {{"enum", nlohmann::json::array({"less", "greater", "same"})}});
  v("verdict", x.verdict,
    "agrees / differs / met_by_constraint (figures; met_by_constraint: within a tolerance the "
    "study imposes as a constraint), confirmed / contradicted / tie (claims; tie: within the "
    "resolution of the methods the values come from, or within a and b's errors)",
    {{"enum", nlohmann::json::array({"agrees", "differs", "met_by_constraint", "confirmed",
                                     "contradicted", "tie", "no_value"})}});
  v.optional("reason", x.reason, "the docs/defects.md entry that explains a difference");
  v("why", x.why, "the reason in one sentence (empty when armstudy agrees)");
}
template <class V>
void fields(V& v, SourceRecord& x) {
  v("document", x.document, "the source the case reproduces");
  v("rows", x.rows, "every figure and claim the source prints for the case");
}
template <class V>
void fields(V& v, ResultsRecord& x) {
  v("schema_version", x.schema_version, "the version of this format; only this one is read",
    {{"const", kSchemaVersion}});
  v("armstudy_version", x.armstudy_version, "the armstudy that wrote it",
    {{"pattern", "^[0-9]+\\.[0-9]+\\.[0-9]+$"}});
  v.optional("git_commit", x.git_commit, "the commit it was built from",
             {{"pattern", "^[0-9a-f]{7,40}(-dirty)?$"}});
  v("study", x.study, "the study; its section is results[study]");
  v("case", x.case_info, "the case file that was run");
  v("provenance", x.provenance, "what produced the numbers and frames");
  v("status", x.status, "whether the study found its answer",
    {{"enum", nlohmann::json::array({"solved", "unsolvable"})}});
  v("message", x.message, "the study's answer (or why there is none) in one sentence");
  v.optional("run_time_s", x.run_time_s,
             "wall-clock seconds from the case's start to this file (solve, sensitivity, frames, "
             "report): junit.xml's time of the case",
             {{"minimum", 0}});
  v("checks", x.checks, "the checks the study ran on its answer");
  v("key_figures", x.key_figures,
    "the numbers a reader compares across cases (none when unsolved)");
  v("run_options", x.run_options,
    "the options of the run that change its output; a later run keeps the output only if they "
    "match its own");
  v("frames", x.frames, "the rendered frame images (PNG), beside results.json");
  v("exports", x.exports,
    "files for other tools, each also under files: model.xml (the case's MJCF with keyframes at "
    "the strip's frame times) and one CSV per motion (a header row with units)");
  v("animations", x.animations,
    "one per rendered motion: frames at equal time steps as a sprite sheet (the report's CSS "
    "animation), its last frame as a still and an MP4 at the motion's real speed");
  v("files", x.files, "every file written beside results.json, with its sha256");
  v.optional("source", x.source,
             "cases that reproduce a source: what it printed beside armstudy's values");
  v.optional("sensitivity", x.sensitivity,
             "cases with a sensitivity part: the answer re-solved at -step and +step of each key");
}

/// The shared record of a whole results.json (results[record.study] is left to the study's
/// reader, StudyEntry::check_results). A schema_version other than kSchemaVersion is an
/// error before anything else is read.
/// @throws ResultsError naming the JSON pointer of the first problem.
ResultsRecord read_record(const nlohmann::json& results);

/// The record as JSON, the study's section not included (run_case adds results[study]).
inline nlohmann::json write_record(const ResultsRecord& r) { return to_json(r); }

}  // namespace armstudy::report
