// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// A MuJoCo client of armstudy's model.xml that knows nothing of armstudy: plain libmujoco
// loads the file, sets each keyframe (mj_resetDataKeyframe), runs mj_forward and prints
// what the key holds as one JSON object: every key's time and the angle of each hinge
// joint by name, and whether its state is finite. tests/e2e/export_clients_test.sh
// compares the angles with the case's motion CSV at the key's time.
//
// usage: keyframe_poses MODEL.xml
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: keyframe_poses MODEL.xml\n");
    return 2;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) {
    std::fprintf(stderr, "%s: %s\n", argv[1], error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  std::printf("{\"nkey\": %d, \"keys\": [", m->nkey);
  for (int k = 0; k < m->nkey; ++k) {
    mj_resetDataKeyframe(m, d, k);
    mj_forward(m, d);
    bool finite = true;
    for (int i = 0; i < m->nq; ++i) finite = finite && std::isfinite(d->qpos[i]);
    for (int i = 0; i < m->nbody * 3; ++i) finite = finite && std::isfinite(d->xpos[i]);
    std::printf("%s\n {\"time\": %.17g, \"finite\": %s, \"joints\": {", k ? "," : "", d->time,
                finite ? "true" : "false");
    bool first = true;
    for (int j = 0; j < m->njnt; ++j) {
      if (m->jnt_type[j] != mjJNT_HINGE) continue;
      const char* name = mj_id2name(m, mjOBJ_JOINT, j);
      std::printf("%s\"%s\": %.17g", first ? "" : ", ", name ? name : "",
                  d->qpos[m->jnt_qposadr[j]]);
      first = false;
    }
    std::printf("}}");
  }
  std::printf("]}\n");
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
