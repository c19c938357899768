// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// What each key of a case file means, by its path (cases::KeyCatalog's): the words the
/// loaders cannot say. Kind, unit, range and default come from the loaders themselves
/// (app/case_keys.hpp); a key read by a loader without an entry here fails
/// tests/cases/case_schema_test.cpp, which names the entry to add.

#include <string>
#include <string_view>
#include <vector>

namespace armstudy::cases {

struct KeyDoc {
  std::string_view study;  ///< "" for every study, else the study whose key it is
  std::string_view
      path;  ///< as KeyInfo::path ("arm.links[].length"); "*.tray.mass_kg": any section's
  std::string_view meaning;  ///< one sentence, unit-free (the unit is the loader's)
  /// YAML text `armstudy init` writes where the loader has no default (a required key, a
  /// list); empty: the key is left out of the case (commented) unless it has a default
  std::string_view example = {};
  /// init writes the key (its default or example) rather than a comment
  bool init = false;
  /// the default in words where the loader's is computed (e.g. "length / 2"), else empty
  std::string_view default_words = {};
};

/// Every key's meaning (cases/key_docs.cpp).
const std::vector<KeyDoc>& key_docs();

/// `d` is the entry of `path` (a path of d is exact, or "*.x.y" for x.y under any section).
bool key_doc_matches(const KeyDoc& d, std::string_view path);

/// The entry of `path` for `study` (its own first, then the one for every study), or null.
const KeyDoc* find_key_doc(std::string_view study, std::string_view path);

}  // namespace armstudy::cases
