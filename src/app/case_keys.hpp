// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The case format, made from the loaders themselves (cases::KeyCatalog): the keys of a case
/// of each study with their kind, unit, range and default, and from them the JSON Schema of
/// case files (case.schema.json), the key reference (docs/case-reference.md) and the case
/// `armstudy init` prints. The meaning of each key is cases/key_docs.cpp's; a key a loader
/// reads without a meaning there is an error (tests/cases/case_schema_test.cpp).

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/key_docs.hpp"
#include "cases/yaml_reader.hpp"

namespace armstudy::app {

/// One key of a study's cases: what its loader reads (info) and what it means (doc; null
/// when cases/key_docs.cpp lacks it).
struct CaseKey {
  cases::KeyInfo info;
  const cases::KeyDoc* doc = nullptr;
};

/// Every key of a case of `study` (a study of study_loaders()), the keys every case has
/// first, in the order the loaders ask for them. Made by running the loaders in catalog
/// mode, once with every key present and again with each key (and each pair of keys of one
/// mapping) they ask has() for left out, so that every branch is walked.
/// @throws std::invalid_argument for a study armstudy does not have.
std::vector<CaseKey> case_keys(std::string_view study);

/// case.schema.json: the JSON Schema (draft-07, as YAML editors read it) of case files, a
/// definition per study chosen by `study:`.
nlohmann::json case_schema();

/// docs/case-reference.md: every key of every study with its type, unit, default, range and
/// meaning.
std::string case_reference_markdown();

/// The case `armstudy init STUDY` prints: every key at its default (commented where it is
/// optional and has none), each with its meaning, naming the schema for editors.
std::string init_case(std::string_view study);

}  // namespace armstudy::app
