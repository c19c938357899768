// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The inputs of a case as results.json echoes them (case.inputs): every value the file
/// writes, by its dotted key path, as YAML text. `armstudy diff` lists the inputs that
/// differ between two runs before what moved.

#include <map>
#include <string>

namespace armstudy::cases {

/// Every value of a case file's text by its key path: a scalar, or a list of scalars as one
/// flow list ("placement.torque_limits_Nm" -> "[40, 40]"); a list of mappings by 1-based
/// index, as the loaders' messages name them ("arm.links[2].length" -> "0.2"). An empty
/// mapping or list is "{}" or "[]". Text that is not YAML gives an empty map (such a case
/// never loads).
std::map<std::string, std::string> case_inputs(const std::string& yaml_text);

}  // namespace armstudy::cases
