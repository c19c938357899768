// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
/// Frames of two runs compared pixel by pixel, with a difference image.

#include <cstddef>
#include <filesystem>
#include <string>

#include "report/diff_report.hpp"

namespace armstudy::cli {

/// The most pixels a frame may have to be decoded (the frame budget, docs/budgets.md); the
/// PNG header's width and height are checked before decoding.
inline constexpr double kMaxFramePixels = 1e8;

/// Compares base/<file> with now/<file>. Byte-identical files are identical; otherwise both
/// are decoded and every pixel with a channel differing by more than `channel_tolerance`
/// (0-255) is counted; a frame is beyond when that count exceeds `pixels_allowed` (or the
/// sizes differ). When the files differ, copies of both and a difference image (the base
/// faded to grey, the pixels beyond in red, their bounding box outlined in magenta) are
/// written to out_dir/<copy_prefix>{base,new,diff}_<file name>, named in the result
/// relative to out_dir. A frame that is missing or cannot be decoded is a FrameDiff with
/// `error` set (and beyond), as is one whose path leaves its case folder (absolute, `..`, a
/// symlink out), one that is not a regular file or a PNG of more than kMaxFramePixels.
/// @throws scene::SceneError when a copy or the difference image cannot be written;
/// cases::InputFileError when a frame is there but no regular file of at most
/// cases::kMaxFrameBytes (a FIFO, a device, a link: never opened for reading).
report::FrameDiff compare_frame(const std::filesystem::path& base, const std::filesystem::path& now,
                                const std::string& file, int channel_tolerance,
                                std::size_t pixels_allowed, const std::filesystem::path& out_dir,
                                const std::string& copy_prefix);

}  // namespace armstudy::cli
