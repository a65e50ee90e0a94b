#include "rtamp/sim/simulation.hpp"

#include <algorithm>
#include <cstring>

#include "rtamp/sim/scene_style.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::sim {

namespace {

Eigen::Isometry3d to_iso(const mjtNum* pos, const mjtNum* xmat) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = xmat[3 * i + j];
  t.linear() = r;
  t.translation() = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  return t;
}

struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};

}  // namespace

int Warnings::total() const {
  int t = 0;
  for (int c : count) t += c;
  return t;
}

const char* Warnings::name(int i) {
  static const char* names[mjNWARNING] = {"inertia", "contact_full", "constraint_full", "vgeom_full",
                                          "bad_qpos", "bad_qvel",     "bad_qacc",        "bad_ctrl"};
  return i >= 0 && i < mjNWARNING ? names[i] : "?";
}

Simulation::Simulation(const world::Scenario& scenario, SimOptions options)
    : scenario_(scenario), options_(std::move(options)) {
  mjcf_ = build_mjcf(scenario_, options_.mjcf);
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(mjcf_.size())) != 0)
    throw Error("MuJoCo: cannot create the in-memory model file");
  int slot = mj_findFileVFS(vfs.get(), "model.xml");
  std::memcpy(vfs->filedata[slot], mjcf_.data(), mjcf_.size());
  char err[1024] = "";
  m_ = mj_loadXML("model.xml", vfs.get(), err, sizeof err);
  if (!m_) throw Error(std::string("MuJoCo cannot load the generated model: ") + err, {scenario_.source, 0, 0});
  d_ = mj_makeData(m_);
  scratch_ = mj_makeData(m_);
  mj_resetDataKeyframe(m_, d_, 0);

  gripper_body_ = mj_name2id(m_, mjOBJ_BODY, "gripper");
  left_body_ = mj_name2id(m_, mjOBJ_BODY, "gripper:left");
  right_body_ = mj_name2id(m_, mjOBJ_BODY, "gripper:right");
  tcp_site_ = mj_name2id(m_, mjOBJ_SITE, "tcp");
  flange_site_ = mj_name2id(m_, mjOBJ_SITE, "flange");
  finger_qpos_ = m_->jnt_qposadr[mj_name2id(m_, mjOBJ_JOINT, "gripper:left")];

  elbow_body_ = mj_name2id(m_, mjOBJ_BODY, "ur5:link3");
  for (const char* n : {"ur5:link2/x", "ur5:link3/x"}) {
    const int g = mj_name2id(m_, mjOBJ_GEOM, n);
    if (g >= 0) big_capsules_.push_back(g);
  }
  arm_body_.assign(static_cast<std::size_t>(m_->nbody), 0);
  for (int b = 0; b < m_->nbody; ++b) {
    const char* n = mj_id2name(m_, mjOBJ_BODY, b);
    if (n && (std::strncmp(n, "ur5:", 4) == 0 || std::strncmp(n, "gripper", 7) == 0)) arm_body_[b] = 1;
  }
  geom_contact_.resize(static_cast<std::size_t>(m_->ngeom));
  for (int g = 0; g < m_->ngeom; ++g) geom_contact_[g] = {m_->geom_contype[g], m_->geom_conaffinity[g]};

  thing_of_body_.assign(static_cast<std::size_t>(m_->nbody), -1);
  auto add_thing = [&](Thing t) {
    t.body = mj_name2id(m_, mjOBJ_BODY, t.body_name.c_str());
    if (t.body < 0) throw Error("MuJoCo model lacks body '" + t.body_name + "'");
    const int j = m_->body_jntadr[t.body];
    t.qpos = m_->jnt_qposadr[j];
    t.dof = m_->jnt_dofadr[j];
    t.eq = mj_name2id(m_, mjOBJ_EQUALITY, ("grasp:" + t.body_name).c_str());
    t.geom_begin = m_->body_geomadr[t.body];
    t.geom_count = m_->body_geomnum[t.body];
    thing_of_body_[t.body] = static_cast<int>(things_.size());
    things_.push_back(std::move(t));
  };
  // Restore the original geom contact bits of spares (built with contacts off).
  for (const auto& c : scenario_.containers)
    add_thing({c.name, c.cls, true, false, true, c.size, "ctr:" + c.name});
  for (const auto& o : scenario_.objects) add_thing({o.name, o.cls, false, false, true, o.size, "obj:" + o.name});
  int park = 0;
  for (int k = 0; k < options_.mjcf.spare_blocks; ++k) {
    Thing t{"", "block", false, true, false, options_.mjcf.spare_block_size, "spare_block:" + std::to_string(k)};
    t.park_index = park++;
    add_thing(std::move(t));
  }
  for (int k = 0; k < options_.mjcf.spare_trays; ++k) {
    Thing t{"", "tray", true, true, false, options_.mjcf.spare_tray_size, "spare_tray:" + std::to_string(k)};
    t.park_index = park++;
    add_thing(std::move(t));
  }
  for (std::size_t i = 0; i < things_.size(); ++i) {
    Thing& t = things_[i];
    if (t.spare) {
      // Spares are built with contacts off; their "on" bits are those of ordinary geoms.
      for (int g = t.geom_begin; g < t.geom_begin + t.geom_count; ++g) geom_contact_[g] = {1, 3};
      hidden_.push_back(static_cast<int>(i));
    }
  }
  for (int j = 0; j < 6; ++j) q_target_[j] = d_->qpos[j];
  finger_target_ = d_->qpos[finger_qpos_];
  mvec_.assign(static_cast<std::size_t>(m_->nv), 0);
  mres_.assign(static_cast<std::size_t>(m_->nv), 0);
  forward();
}

Simulation::~Simulation() {
  if (scratch_) mj_deleteData(scratch_);
  if (d_) mj_deleteData(d_);
  if (m_) mj_deleteModel(m_);
}

void Simulation::forward() { mj_forward(m_, d_); }

void Simulation::park(const Thing& t) {
  world::Vec3 p = parking_position(t.park_index >= 0 ? t.park_index : 0);
  mjtNum* q = d_->qpos + t.qpos;
  q[0] = p[0], q[1] = p[1], q[2] = p[2], q[3] = 1, q[4] = q[5] = q[6] = 0;
  for (int k = 0; k < 6; ++k) d_->qvel[t.dof + k] = 0;
}

void Simulation::set_contacts(const Thing& t, bool on) {
  for (int g = t.geom_begin; g < t.geom_begin + t.geom_count; ++g) {
    m_->geom_contype[g] = on ? geom_contact_[g][0] : 0;
    m_->geom_conaffinity[g] = on ? geom_contact_[g][1] : 0;
  }
}

void Simulation::step() {
  for (int i : hidden_) park(things_[static_cast<std::size_t>(i)]);
  mj_step1(m_, d_);
  for (int j = 0; j < 6; ++j) {
    d_->ctrl[j] = q_target_[j];
    mvec_[j] = qdd_target_[j];
  }
  d_->ctrl[6] = d_->ctrl[7] = finger_target_;
  mj_mulM(m_, d_, mres_.data(), mvec_.data());
  bool limited = false;
  for (int j = 0; j < 6; ++j) {
    // Actuator j drives arm joint j = dof j (mjcf_builder.hpp). Its servo force is
    // kp (q* − q) clamped to forcerange; the rest of the motor torque must fit beside it.
    const double damping = m_->dof_damping[j];
    double servo = m_->actuator_gainprm[mjNGAIN * j] * (q_target_[j] - d_->qpos[j]);
    double lo = -mjMAXVAL, hi = mjMAXVAL;
    if (m_->actuator_forcelimited[j]) {
      lo = m_->actuator_forcerange[2 * j], hi = m_->actuator_forcerange[2 * j + 1];
      servo = std::clamp(servo, lo, hi);
    }
    const double ff = d_->qfrc_bias[j] + mres_[j] + damping * (qd_target_[j] - d_->qvel[j]);
    const double ff_limited = std::clamp(ff, lo - servo, hi - servo);
    if (ff_limited != ff || servo == lo || servo == hi) limited = true;
    // MuJoCo subtracts damping * qd itself (implicitly): add it back here.
    d_->qfrc_applied[j] = ff_limited + damping * d_->qvel[j];
  }
  if (limited) ++torque_limited_steps_;
  mj_step2(m_, d_);
}

void Simulation::set_arm_target(const robot::Joints& q, const robot::Joints& qd, const robot::Joints& qdd) {
  q_target_ = q;
  qd_target_ = qd;
  qdd_target_ = qdd;
}

void Simulation::set_finger_target(double half_opening) {
  finger_target_ = std::clamp(half_opening, 0.0, options_.mjcf.finger_max);
}

robot::Joints Simulation::arm_q() const {
  robot::Joints q;
  for (int j = 0; j < 6; ++j) q[j] = d_->qpos[j];
  return q;
}

robot::Joints Simulation::arm_qd() const {
  robot::Joints q;
  for (int j = 0; j < 6; ++j) q[j] = d_->qvel[j];
  return q;
}

double Simulation::finger_opening() const { return 0.5 * (d_->qpos[finger_qpos_] + d_->qpos[finger_qpos_ + 1]); }

double Simulation::finger_speed() const {
  const int v = m_->jnt_dofadr[m_->body_jntadr[left_body_]];
  return 0.5 * (std::abs(d_->qvel[v]) + std::abs(d_->qvel[v + 1]));
}

Eigen::Isometry3d Simulation::site_pose(int site) const {
  return to_iso(d_->site_xpos + 3 * site, d_->site_xmat + 9 * site);
}

void Simulation::set_arm_configuration(const robot::Joints& q) {
  for (int j = 0; j < 6; ++j) {
    d_->qpos[j] = q[j];
    d_->qvel[j] = 0;
  }
  set_arm_target(q);
  forward();
}

int Simulation::find(const std::string& name) const {
  if (name.empty()) return -1;
  for (std::size_t i = 0; i < things_.size(); ++i)
    if (things_[i].name == name) return static_cast<int>(i);
  return -1;
}

Eigen::Isometry3d Simulation::pose(int i) const {
  const Thing& t = thing(i);
  return to_iso(d_->xpos + 3 * t.body, d_->xmat + 9 * t.body);
}

Eigen::Vector3d Simulation::position(int i) const {
  const mjtNum* p = d_->xpos + 3 * thing(i).body;
  return {p[0], p[1], p[2]};
}

Eigen::Vector3d Simulation::velocity(int i) const {
  const mjtNum* v = d_->qvel + thing(i).dof;
  return {v[0], v[1], v[2]};
}

void Simulation::set_pose(int i, const Eigen::Isometry3d& p) {
  const Thing& t = thing(i);
  mjtNum* q = d_->qpos + t.qpos;
  Eigen::Quaterniond r(p.linear());
  r.normalize();
  q[0] = p.translation().x(), q[1] = p.translation().y(), q[2] = p.translation().z();
  q[3] = r.w(), q[4] = r.x(), q[5] = r.y(), q[6] = r.z();
  for (int k = 0; k < 6; ++k) d_->qvel[t.dof + k] = 0;
  forward();
}

void Simulation::hide(int i) {
  Thing& t = things_[static_cast<std::size_t>(i)];
  if (!t.present) return;
  if (held_ == i) detach();
  if (t.park_index < 0) {
    // A scenario body gets a parking slot after the spares' slots.
    int used = 0;
    for (const Thing& o : things_) used = std::max(used, o.park_index + 1);
    t.park_index = used;
  }
  t.present = false;
  set_contacts(t, false);
  park(t);
  hidden_.push_back(i);
  forward();
}

void Simulation::show(int i, const Eigen::Isometry3d& p) {
  Thing& t = things_[static_cast<std::size_t>(i)];
  if (t.present) {
    set_pose(i, p);
    return;
  }
  t.present = true;
  std::erase(hidden_, i);
  set_contacts(t, true);
  set_pose(i, p);
}

int Simulation::add(const std::string& name, const std::string& cls, bool container, const Eigen::Isometry3d& p,
                    const world::Vec3& size) {
  if (find(name) >= 0) {
    int i = find(name);
    if (things_[static_cast<std::size_t>(i)].present) throw Error("cannot add '" + name + "': it is already there");
    show(i, p);
    return i;
  }
  for (std::size_t i = 0; i < things_.size(); ++i) {
    Thing& t = things_[i];
    if (!t.spare || !t.name.empty() || t.container != container) continue;
    t.name = name;
    t.cls = cls;
    const auto rgb = class_colour(scenario_, cls);  // spares are built in the default class's colour
    for (int g = t.geom_begin; g < t.geom_begin + t.geom_count; ++g)
      for (int k = 0; k < 3; ++k) m_->geom_rgba[4 * g + k] = static_cast<float>(rgb[static_cast<std::size_t>(k)]);
    if (!container) {
      // Resize the box (collision and visual); keep mass and inertia.
      const int g = t.geom_begin;
      m_->geom_size[3 * g] = size[0] / 2, m_->geom_size[3 * g + 1] = size[1] / 2, m_->geom_size[3 * g + 2] = size[2] / 2;
      m_->geom_rbound[g] = 0.5 * std::sqrt(size[0] * size[0] + size[1] * size[1] + size[2] * size[2]);
      t.size = size;
    }
    show(static_cast<int>(i), p);
    return static_cast<int>(i);
  }
  const int reserved = container ? options_.mjcf.spare_trays : options_.mjcf.spare_blocks;
  throw Error(std::string("cannot add '") + name + "': the simulation has no spare " + (container ? "tray" : "block") +
              " body left (it reserves " + std::to_string(reserved) + " for things added during a run)");
}

bool Simulation::fingers_touch(int i) const {
  const int body = thing(i).body;
  bool left = false, right = false;
  for (int c = 0; c < d_->ncon; ++c) {
    const mjContact& con = d_->contact[c];
    const int b1 = m_->geom_bodyid[con.geom1], b2 = m_->geom_bodyid[con.geom2];
    const int other = b1 == body ? b2 : (b2 == body ? b1 : -1);
    if (other == left_body_) left = true;
    if (other == right_body_) right = true;
  }
  return left && right;
}

void Simulation::attach(int i) {
  if (held_ >= 0) detach();
  const Thing& t = thing(i);
  const mjtNum* p1 = d_->xpos + 3 * gripper_body_;
  const mjtNum* q1 = d_->xquat + 4 * gripper_body_;
  const mjtNum* p2 = d_->xpos + 3 * t.body;
  const mjtNum* q2 = d_->xquat + 4 * t.body;
  mjtNum* e = m_->eq_data + mjNEQDATA * t.eq;
  mjtNum dp[3] = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
  mjtNum q1c[4];
  mju_negQuat(q1c, q1);
  e[0] = e[1] = e[2] = 0;
  mju_rotVecQuat(e + 3, dp, q1c);
  mju_mulQuat(e + 6, q1c, q2);
  m_->eq_active[t.eq] = 1;
  held_ = i;
}

void Simulation::detach() {
  reserved_.reset();
  if (held_ < 0) return;
  m_->eq_active[thing(held_).eq] = 0;
  held_ = -1;
}

bool Simulation::config_collides(const robot::Joints& q, const std::vector<int>& ignore) const {
  mjData* s = scratch_;
  std::memcpy(s->qpos, d_->qpos, sizeof(mjtNum) * static_cast<std::size_t>(m_->nq));
  for (int j = 0; j < 6; ++j) s->qpos[j] = q[j];
  if (held_ >= 0) {
    // Carry the held thing along: its pose relative to the gripper stays as welded.
    mj_kinematics(m_, s);
    const Thing& t = thing(held_);
    const mjtNum* e = m_->eq_data + mjNEQDATA * t.eq;
    const mjtNum* p1 = s->xpos + 3 * gripper_body_;
    const mjtNum* q1 = s->xquat + 4 * gripper_body_;
    mjtNum dp[3];
    mju_rotVecQuat(dp, e + 3, q1);
    mjtNum* qp = s->qpos + t.qpos;
    qp[0] = p1[0] + dp[0], qp[1] = p1[1] + dp[1], qp[2] = p1[2] + dp[2];
    mju_mulQuat(qp + 3, q1, e + 6);
  }
  mj_kinematics(m_, s);
  if (s->xpos[3 * elbow_body_ + 2] < options_.min_elbow_height) return true;
  for (int g : big_capsules_) {
    // A capsule's axis is its local z; half-length size[1], radius size[0].
    const mjtNum* c = s->geom_xpos + 3 * g;
    const mjtNum axis_z = s->geom_xmat[9 * g + 8];
    const mjtNum lowest = c[2] - std::abs(axis_z) * m_->geom_size[3 * g + 1] - m_->geom_size[3 * g];
    if (lowest < options_.arm_table_clearance) return true;
  }
  mj_collision(m_, s);
  const double tol = options_.collision_tolerance;
  const int held_body = held_ >= 0 ? thing(held_).body : -1;
  for (int c = 0; c < s->ncon; ++c) {
    const mjContact& con = s->contact[c];
    const int b1 = m_->geom_bodyid[con.geom1], b2 = m_->geom_bodyid[con.geom2];
    if (con.dist >= -tol) continue;
    const int t1 = thing_of_body_[b1], t2 = thing_of_body_[b2];
    if ((t1 >= 0 && std::find(ignore.begin(), ignore.end(), t1) != ignore.end()) ||
        (t2 >= 0 && std::find(ignore.begin(), ignore.end(), t2) != ignore.end()))
      continue;
    const bool r1 = arm_body_[b1] || b1 == held_body, r2 = arm_body_[b2] || b2 == held_body;
    if (!r1 && !r2) continue;  // world against world: not the arm's business
    if (r1 && r2) continue;    // hand against held thing
    return true;
  }
  return false;
}

Warnings Simulation::warnings() const {
  Warnings w;
  for (int i = 0; i < mjNWARNING; ++i) w.count[i] = d_->warning[i].number;
  return w;
}

}  // namespace rtamp::sim
