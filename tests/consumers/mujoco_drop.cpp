// impact-drop-mujoco EXPORT_DIR OUTPUT.json: loads the exported MJCF (mujoco/impact_contact.xml)
// in MuJoCo 2.2.2 as it is, drops its sphere on its plane at each campaign velocity with
// mj_step, measures restitution, contact time and peak force from MuJoCo's own state and
// contact force (mj_contactForce), and writes them with their errors (format
// "impact-simulator-run").

#include "simulator_run.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using impact::consumers::DropFigures;
using impact::consumers::DropSample;

struct ModelDeleter {
  void operator()(mjModel* model) const { mj_deleteModel(model); }
};
struct DataDeleter {
  void operator()(mjData* data) const { mj_deleteData(data); }
};

DropFigures drop(const mjModel* model, double velocity) {
  std::unique_ptr<mjData, DataDeleter> data(mj_makeData(model));
  const int sphere = mj_name2id(model, mjOBJ_GEOM, "sphere");
  const int joint = mj_name2id(model, mjOBJ_JOINT, "sphere");
  if (sphere < 0 || joint < 0) throw std::runtime_error("the model has no geom and joint 'sphere'");
  const double radius = model->geom_size[3 * sphere];
  const int q = model->jnt_qposadr[joint], u = model->jnt_dofadr[joint];
  // Half a step above the plane, moving down (free joint: position then quaternion).
  data->qpos[q + 2] = radius + 0.5 * velocity * model->opt.timestep;
  data->qvel[u + 2] = -velocity;
  std::vector<DropSample> samples;
  const auto record = [&] {
    double force = 0;
    for (int c = 0; c < data->ncon; ++c) {
      mjtNum frame_force[6];
      mj_contactForce(model, data.get(), c, frame_force);
      force += frame_force[0]; // normal component, in the contact frame
    }
    samples.push_back({data->time, radius - data->qpos[q + 2], force});
  };
  mj_forward(model, data.get());
  record();
  bool touched = false;
  for (long step = 0; step < 100000000; ++step) {
    mj_step(model, data.get());
    mj_forward(model, data.get()); // the contact force of the new state, not of the last
    record();
    touched = touched || samples.back().approach > 0;
    // Done once the sphere is clear of the plane after the contact.
    if (touched && samples.back().approach < 0) break;
  }
  return impact::consumers::measure_drop(samples, velocity, data->qvel[u + 2]);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-mujoco EXPORT_DIR OUTPUT.json\n");
    return 2;
  }
  try {
    const auto entries = impact::consumers::read_export(argv[1], "mujoco");
    const auto& entry = entries.front();
    const std::string file = (entry.directory / entry.file).string();
    char error[1000] = "";
    std::unique_ptr<mjModel, ModelDeleter> model(
        mj_loadXML(file.c_str(), nullptr, error, sizeof error));
    if (!model) throw std::runtime_error(file + ": " + error);
    std::vector<DropFigures> measured;
    for (double velocity : entry.velocities) measured.push_back(drop(model.get(), velocity));
    impact::consumers::write_simulator_run(argv[2], entry, mj_versionString(), measured);
    impact::consumers::print_simulator_run(entry, measured);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-mujoco: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
