// A belief about where things are, kept from what a camera sees frame by frame (paper
// Section V: the robot knows the world only through its camera). It keeps what the camera
// cannot see right now: each thing is Visible, Occluded (its spot is covered, by the arm
// say), Held (it follows the gripper), OutOfView, or Missing (its spot is in view and
// uncovered, and nothing of its class is there). Its placement is read with the same
// Geometry as the planner's (geometry.hpp), from the believed poses.
//
// Rules (docs/perception.md "The belief", with the measurements that chose the numbers):
//  - A detection is matched to the nearest believed thing of its class within
//    match_radius in the table's plane (greedily, nearest pairs first); a complete
//    detection sets the pose, an incomplete one (within the thing's half diagonal) only
//    says the thing is there.
//  - A thing is believed removed only after it has been Missing for remove_after seconds,
//    on a frame that judges it Missing (never on one that does not see its spot).
//  - A detection no thing explains is a candidate (at its last complete pose, if any): a
//    thing within match_radius explains it (its reach for an incomplete one: a second
//    view of it), unless both are whole — a complete detection beside a thing that frame
//    saw complete elsewhere is another thing (a look-alike pushed against it). After
//    confirm_sightings sightings
//    (each within candidate_timeout of the last) it is a Missing thing of its class that
//    moved there (the nearest one), or else the one of its class believed removed last
//    within reidentify_within seconds (moved where the camera could not see), or else —
//    after waiting up to hidden_wait while a thing of its class is occluded (it may be
//    that one, moved) — a new thing. A thing not seen yet matches within
//    first_sight_radius of where the scenario declares it. A thing that a candidate seen
//    only in part became is provisional: each sighting sets its pose until a complete one.
//  - A grasp that closed on nothing is a look with the fingers: the thing believed where
//    the tool point was (inside its box; a block before the tray it lies on) and not seen
//    in that frame is believed removed at once (and, seen again within reidentify_within, is the same thing where it is seen).
//    A grasp that failed otherwise proves its pose wrong: the next sighting of the thing,
//    even an incomplete one, sets it.
//  - A container's contents move with it (carried in the gripper too); the held thing
//    keeps the offset to the tool it had when grasped. A thing the hand lets go of in the
//    air (its base above rest_height: taken from the gripper, say), with what it carried,
//    and not seen there in that frame is believed removed at once (and re-identified if
//    seen again within reidentify_within). A detection in the air (base above
//    rest_height) matches only a thing believed in the air, and never starts a candidate;
//    one below the table (a side face taken for a top) is no evidence at all.
// The belief never reads the truth: it sees detections, a visibility model and what the
// robot knows of its own gripper. Storage is kept between frames.
#pragma once

#include <string>
#include <vector>

#include "rtamp/world/geometry.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// A thing of a class seen in one frame: its base centre and yaw (the box fit of perception).
struct Detection {
  std::string cls;
  Vec3 base{};
  double yaw = 0;
  bool complete = true;  // the whole outline was seen: the pose can be trusted
};

enum class ThingState { Visible, Occluded, Held, OutOfView, Missing };
const char* to_string(ThingState s);

struct BelievedThing {
  std::string name, cls;
  bool container = false;
  Vec3 size{};
  Vec3 base{};  // centre of the base, world frame
  double yaw = 0;
  ThingState state = ThingState::OutOfView;
  double last_seen = -1;      // world time of the last match; < 0: never seen
  double missing_since = -1;  // world time it became Missing
  std::string on;             // the container it rested in at the last frame ("" if none)
  bool doubted = false;       // a grasp at this pose failed: the next sighting sets the pose
  bool provisional = false;   // the pose is from partial sightings only: each sighting sets it
};

// What a camera could say of a spot where a thing is believed to be: it would be seen
// there (Visible), something covers it (Occluded), or it lies outside the image (OutOfView).
// With several cameras, a spot outside this frame's image but inside another camera's
// (at that camera's last frame) is Elsewhere: this frame says nothing of the thing, whose
// state and Missing clock stay as the camera that sees it left them.
enum class Sight { Visible, Occluded, OutOfView, Elsewhere };

// The camera side of the belief: a user's own perception implements it.
class Visibility {
 public:
  virtual ~Visibility() = default;
  virtual Sight sight(const BelievedThing& thing) const = 0;
};

// What the robot knows of its own gripper.
struct Gripper {
  std::string holds;  // the thing it grasped ("" when empty)
  Vec3 tool{};        // the tool point (world)
  // The last grasp that failed: when (< 0: none), the tool point then, and whether the
  // fingers closed on nothing (else they stopped on something they could not hold).
  double failed_grasp_at = -1;
  Vec3 failed_grasp_tool{};
  bool failed_grasp_empty = false;
};

struct BeliefOptions {
  double match_radius = 0.05;     // m, base to base in the table's plane
  double remove_after = 0.3;      // s Missing before a thing is believed removed
  int confirm_sightings = 2;      // sightings that make a candidate a thing
  double candidate_timeout = 0.5; // s between a candidate's sightings at most
  double rest_height = 0.05;      // m: a base higher than this is in the air
  double reidentify_within = 5;   // s: a thing removed this recently may turn up again
  double hidden_wait = 8;         // s a confirmed candidate waits at most while a thing of its class is occluded
  double first_sight_radius = 0.3;  // m: a thing never seen yet matches this far from where it was declared
};

class Belief {
 public:
  // The things the scenario declares, where it declares them (not yet seen). Throws
  // rtamp::Error on options out of range.
  explicit Belief(const Scenario& s, BeliefOptions options = {});

  // One frame at world `time` (not earlier than the last).
  void update(double time, const std::vector<Detection>& seen, const Visibility& visibility, const Gripper& gripper);

  const std::vector<BelievedThing>& things() const { return things_; }
  const BelievedThing* find(const std::string& name) const;
  // Every believed thing's location: the held one "hand", the others where their base lies.
  Placement placement() const;
  const BeliefOptions& options() const { return options_; }
  // Whether a change is seen but not believed yet: a sighting not yet a thing (a
  // candidate, waiting for its sightings or for a hidden thing of its class), or a thing
  // Missing not yet long enough to be removed. At most hidden_wait after it began.
  bool confirming() const;

 private:
  struct Candidate {
    Detection seen;
    int sightings = 0;
    double last_seen = 0;
    double first_seen = 0;
  };
  void follow_gripper(const Gripper& g);
  void match(double time, const std::vector<Detection>& seen);
  void feel_let_go(double time);
  void feel_failed_grasp(double time, const Gripper& g);
  void judge_unseen(double time, const Visibility& visibility);
  void carry_contents(const std::vector<Vec3>& before);
  void promote(double time, const std::vector<Detection>& seen);
  void locate_all();
  std::string fresh_name(const std::string& cls);

  BeliefOptions options_;
  Geometry geometry_;
  std::vector<BelievedThing> things_;
  std::vector<Candidate> candidates_;
  struct Removed {
    BelievedThing thing;
    double time = 0;
  };
  std::vector<Removed> removed_;  // within reidentify_within
  struct ClassInfo {
    std::string cls;
    bool container = false;
    Vec3 size{};  // of the first thing of the class the scenario declares
  };
  std::vector<ClassInfo> classes_;
  std::string held_;
  Vec3 held_offset_{};
  double failed_grasp_at_ = -1;  // the last failed grasp taken as evidence
  std::string let_go_;          // the thing the hand let go of in the air this frame
  double time_ = 0;
  int added_ = 0;  // things the belief has named
  // Per frame scratch, kept to spare allocations.
  std::vector<char> used_;
  std::vector<char> matched_;
  std::vector<char> whole_;  // this frame matched the thing to a complete detection
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> pairs_;
  std::vector<Vec3> before_;  // containers' bases at the frame's start
};

}  // namespace rtamp::world
