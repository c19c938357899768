#include "scene/study_frames.hpp"

#include "scene/png_writer.hpp"

namespace armstudy::scene {

RenderSettings render_settings(const cases::RenderOptions& o) {
  RenderSettings s;
  s.width = o.width;
  s.height = o.height;
  s.shadows = o.shadows;
  return s;
}

std::string write_strip(SceneRenderer& sr, const SampledMotion& m, int frames,
                        const std::string& title, const std::filesystem::path& dir,
                        const std::string& name) {
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), frames);
  const std::vector<PoseSample> samples = resample(m.t, m.q, m.qd, at);
  const std::string file = name + "_strip.png";
  write_png(dir / file, sr.strip(samples, title, strip_columns(frames)));
  return file;
}

std::string write_locus(SceneRenderer& sr, const SampledMotion& m, int poses,
                        std::span<const Eigen::Vector2d> path,
                        std::span<const Eigen::Vector2d> flight, const FrameLabels& labels,
                        const std::filesystem::path& dir, const std::string& name) {
  const std::vector<double> at = even_times(m.t.front(), m.t.back(), poses);
  const std::vector<PoseSample> samples = resample(m.t, m.q, m.qd, at);
  const std::string file = name + "_locus.png";
  write_png(dir / file, sr.locus(samples, path, flight, labels));
  return file;
}

}  // namespace armstudy::scene
