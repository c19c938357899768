// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// The bytes of a YAML file checked before yaml-cpp builds a tree of them, so that hostile
/// input is refused quickly with its file:line:col instead of hanging, crashing or running
/// away with memory:
/// - only a regular file is read (a folder, FIFO or device is refused without reading),
///   at most kMaxFileBytes (input_file.hpp, as every file armstudy reads);
/// - the text is UTF-8 without NUL bytes or other control characters but tab, LF and CR;
/// - the file holds one YAML document (text after `...` or a second `---` is refused);
/// - nesting is at most kMaxDepth levels deep, keys are plain scalars (no complex keys),
///   an alias never refers to the node it is inside (recursion), and the document,
///   every alias expanded, has at most kMaxNodes nodes (an alias bomb stays small on disk
///   and is refused here, before anything walks it).

#include <cstddef>
#include <string>

#include <yaml-cpp/yaml.h>

namespace armstudy::cases {

class Diagnostics;

/// 16 MiB: case and sweep files are a few kB; anything this big is not one.
inline constexpr std::size_t kMaxFileBytes = std::size_t(16) << 20;
/// Nested lists and mappings; case files use fewer than 10.
inline constexpr int kMaxDepth = 64;
/// Nodes of the document with every alias expanded (a case file has a few hundred).
inline constexpr std::size_t kMaxNodes = 200000;

/// Reads the bytes of a regular file of at most kMaxFileBytes into `bytes`; otherwise
/// records why not (no position) and returns false. Never blocks on a FIFO
/// (read_input_file).
bool read_regular_file(const std::string& path, Diagnostics& diag, std::string* bytes);

/// Checks the text (UTF-8, no NUL or control characters) and its YAML structure (one
/// document, depth, complex keys, aliases, size) as above; records the first problem at
/// its line:col and returns false. A syntax error is recorded as "not valid YAML".
bool check_yaml_source(const std::string& bytes, Diagnostics& diag);

/// `s` for a message: control characters escaped (\n, \t, \x1B), characters that print
/// as nothing or reorder text (zero-width space, byte order mark, direction marks) as
/// \u200b; at most `max_chars` characters (a longer text is cut and says how long it was).
/// Never quotes a whole file.
std::string brief(const std::string& s, std::size_t max_chars = 60);

}  // namespace armstudy::cases
