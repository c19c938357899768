#pragma once
/// Frames of the time-optimal study: the exact (reachability) solution at equal time steps
/// along its path (a strip), and a locus of all of them with the path traced.

#include <filesystem>
#include <string>
#include <vector>

#include "cases/case_info.hpp"
#include "studies/time_optimal/result.hpp"
#include "studies/time_optimal/spec.hpp"

namespace armstudy::scene {

/// Writes time_optimal_{strip,locus}.png into `dir`; returns the file names.
/// @throws SceneError.
std::vector<std::string> render_time_optimal_frames(const studies::time_optimal::Spec& spec,
                                                    const studies::time_optimal::Result& result,
                                                    const cases::RenderOptions& options,
                                                    const std::filesystem::path& dir);

}  // namespace armstudy::scene
