// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "scene/model_export.hpp"

#include <fstream>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "scene/chain_map.hpp"
#include "scene/frames.hpp"
#include "scene/mujoco_model.hpp"
#include "scene/png_writer.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::scene {

std::vector<PoseSample> strip_keyframes(const SampledMotion& m, int frames) {
  if (m.t.empty() || frames < 1) return {};
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), frames);
  return resample(m.t, m.q, m.qd, at);
}

std::string mjcf_with_keyframes(const core::PlanarChain& chain, const std::string& mjcf,
                                std::span<const PoseSample> keys, const std::string& motion,
                                const std::string& source) {
  const size_t end = mjcf.rfind("</mujoco>");
  if (end == std::string::npos) throw ModelError(source + ": the generated MJCF has no </mujoco>");
  MujocoModel mm(mjcf, source);
  const ChainMap map(chain, mm.model());
  const mjModel* m = mm.model();
  std::ostringstream x;
  x.imbue(std::locale::classic());
  x.precision(17);
  x << "  <!--\n    keyframes: the " << keys.size() << " frames of the strip of " << motion
    << ", at the strip's times (key time, qpos and qvel in MuJoCo's coordinates);\n"
    << "    in MuJoCo's simulate, open the Simulation panel and load key 1, 2, ... to step\n"
    << "    through the motion pose by pose.\n  -->\n"
    << "  <keyframe>\n";
  for (size_t k = 0; k < keys.size(); ++k) {
    const PoseSample& p = keys[k];
    if (p.q.size() != chain.num_links() || (p.qd.size() != 0 && p.qd.size() != chain.num_links()))
      throw std::invalid_argument("keyframe " + std::to_string(k + 1) + " has " +
                                  std::to_string(p.q.size()) + " joint angles; the chain has " +
                                  std::to_string(chain.num_links()));
    const core::JointVector qd = p.qd.size() ? p.qd : core::JointVector::Zero(chain.num_links());
    map.set_state(m, mm.data(), p.q, qd);
    x << "    <key name=\"frame" << k + 1 << "\" time=\"" << p.t << "\" qpos=\"";
    for (int i = 0; i < m->nq; ++i) x << (i ? " " : "") << mm.data()->qpos[i];
    x << "\" qvel=\"";
    for (int i = 0; i < m->nv; ++i) x << (i ? " " : "") << mm.data()->qvel[i];
    x << "\"/>\n";
  }
  x << "  </keyframe>\n";
  std::string out = mjcf;
  out.insert(end, x.str());
  return out;
}

std::string write_model_xml(const std::filesystem::path& dir, const core::PlanarChain& chain,
                            const std::string& mjcf, std::span<const PoseSample> keys,
                            const std::string& motion, const std::string& source) {
  const std::string text = mjcf_with_keyframes(chain, mjcf, keys, motion, source);
  const std::filesystem::path path = dir / kModelFile;
  write_bytes(path, text);  // the error says why (No space left on device)
  return kModelFile;
}

}  // namespace armstudy::scene
