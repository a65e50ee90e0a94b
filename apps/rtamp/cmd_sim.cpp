// rtamp sim — run an action list in the MuJoCo simulation of a scenario, headless and
// as fast as the CPU allows (sim/session.hpp), or write the generated MJCF:
//   rtamp sim 3-block-tray --do "move o1 r3; move r3 r2" [--json] [--seed N]
//        [--snapshot out.png] [--video out.mp4] [--operator] [--mjcf model.xml]
//        [--camera NAME] [--depth depth.png] [--segmentation seg.png] [--perception camera]
//        [--perception-cameras NAME,...]
// With --perception camera the robot perceives through the cameras (--perception-cameras,
// else --camera, else the scenario's primary one) and a belief (sim/perception.hpp);
// "perceived" is then the belief.
// With --camera (or --depth / --segmentation, which use the scenario's primary
// camera when no --camera is given), --snapshot writes that camera's RGB instead of
// the overview picture (sim/camera_snapshot.hpp).
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/output_file.hpp"
#include "rtamp/util/text_file.hpp"
#include "episode_args.hpp"
#include "options.hpp"
#include "rtamp/episode/world_registry.hpp"
#include "rtamp/sim/action_check.hpp"
#include "rtamp/sim/camera_perception.hpp"
#include "rtamp/sim/camera_snapshot.hpp"
#include "rtamp/sim/session.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

struct SimArgs {
  std::string scenario;
  std::string actions;
  std::string mjcf;
  std::string snapshot;
  std::string camera, depth, segmentation;
  std::string video;
  std::string perception = "truth";
  std::vector<std::string> perception_cameras;
  bool json = false;
  bool scripted = false;
  double random_rate = 0;
  double noise = 0;
  double miss = 0;
  std::uint64_t seed = 1;
  int width = 640, height = 480;
};

void write_file(const std::string& path, const std::string& text) { rtamp::write_output_file(path, "--mjcf", text); }

rtamp::cli::Registrar reg{
    "sim", "Run actions in the MuJoCo simulation of a scenario (headless), or write its MJCF",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto a = std::make_shared<SimArgs>();
      rtamp::cli::add_scenario(sub, a->scenario)->required();
      sub.add_option("--do", a->actions,
                     "Actions separated by ';': move THING LOC | pick THING | place LOC | wait SECONDS");
      sub.add_option("--mjcf", a->mjcf, "Write the generated MuJoCo model (MJCF XML) to this file");
      sub.add_flag("--json", a->json, "Print one JSON object instead of text");
      rtamp::cli::add_seed(sub, "--seed", a->seed, "Seed of perception noise and the random operator");
      sub.add_flag("--operator", a->scripted, "Apply the scenario's scripted operator interventions");
      rtamp::cli::add_real(sub, "--random-interventions", a->random_rate, {0, 10},
                           "Random operator interventions per simulated second (relocate, add, remove)");
      rtamp::cli::add_real(sub, "--noise", a->noise, {0, 1}, "Perception: standard deviation of x, y position noise (m)");
      rtamp::cli::add_real(sub, "--miss", a->miss, {0, 1}, "Perception: probability of missing a thing");
      sub.add_option("--perception", a->perception,
                     "How the robot perceives: truth (the simulation's poses) or camera (RGB-D frames of --camera, "
                     "else the primary camera, segmented and fitted from pixels and kept in a belief)")
          ->check(CLI::IsMember({"truth", "camera"}));
      rtamp::cli::add_perception_cameras(sub, a->perception_cameras);
      sub.add_option("--snapshot", a->snapshot, "Render the final scene to this PNG file");
      sub.add_option("--camera", a->camera,
                     "Write --snapshot from this camera of the scenario (docs/perception.md) instead of the overview");
      sub.add_option("--depth", a->depth, "Write the camera's depth to this 16-bit PNG (millimetres, 0 = no reading)");
      sub.add_option("--segmentation", a->segmentation,
                     "Write the camera's segmentation pass to this PNG (one colour per body)");
      sub.add_option("--video", a->video, "Record the run to this MP4 file (ffmpeg)");
      rtamp::cli::add_integer(sub, "--width", a->width, 16, 4096, "Image width for --snapshot/--video");
      rtamp::cli::add_integer(sub, "--height", a->height, 16, 4096, "Image height for --snapshot/--video");
      return [a]() -> int {
        using namespace rtamp;
        const world::Scenario scenario = world::load_scenario(a->scenario);
        task::validate_task(scenario);
        const std::vector<sim::SimAction> actions = sim::parse_actions(a->actions);
        sim::check_actions(actions, scenario, a->actions, a->scripted);  // before anything moves
        const std::vector<world::Camera> cameras = world::cameras_of(scenario);
        const bool use_camera = !a->camera.empty() || !a->depth.empty() || !a->segmentation.empty();
        const std::string camera_name =
            a->camera.empty() ? world::primary_camera(cameras).name
                              : world::find_camera(cameras, a->camera, SourceLocation{"--camera", 1, 1}).name;
        std::vector<std::string> perceiving = episode::perception_cameras(
            scenario, episode::WorldSettings{.perception = a->perception, .perception_cameras = a->perception_cameras});
        if (perceiving.empty()) perceiving.push_back(camera_name);
        // Outputs first: a bad path is refused before the simulation starts.
        {  // no output is the scenario or another output (by device and inode)
          rtamp::FileSet files;
          if (rtamp::path_exists(a->scenario)) files.input("SCENARIO", a->scenario);
          for (const auto& [option, path] : {std::pair<const char*, const std::string*>{"--depth", &a->depth},
                                             {"--segmentation", &a->segmentation}, {"--video", &a->video},
                                             {"--snapshot", &a->snapshot}, {"--mjcf", &a->mjcf}})
            if (!path->empty()) files.output(option, *path);
        }
        if (!a->depth.empty()) rtamp::cli::check_output_file("--depth", a->depth);
        if (!a->segmentation.empty()) rtamp::cli::check_output_file("--segmentation", a->segmentation);
        if (!a->video.empty()) rtamp::cli::check_output_file("--video", a->video);
        if (!a->snapshot.empty()) rtamp::cli::check_output_file("--snapshot", a->snapshot);
        if (!a->mjcf.empty()) rtamp::cli::check_output_file("--mjcf", a->mjcf);
        sim::SessionOptions opt;
        opt.seed = a->seed;
        opt.scripted_operator = a->scripted;
        opt.person.rate = a->random_rate;
        opt.perception.position_sigma = a->noise;
        opt.perception.miss_probability = a->miss;
        opt.perception.source = sim::parse_perception_source(a->perception);
        opt.perception.cameras = perceiving;
        opt.video_path = a->video;
        opt.render.width = a->width;
        opt.render.height = a->height;
        sim::Session session(scenario, opt);
        if (!a->mjcf.empty()) write_file(a->mjcf, session.sim().mjcf());
        auto print_action = [&](const sim::ActionResult& r) {
          if (a->json) return;
          std::cout << std::left << std::setw(22) << r.action << std::right << ' ' << std::setw(7)
                    << sim::to_string(r.status) << "  cost " << std::fixed << std::setprecision(3) << r.cost
                    << " m  sim " << std::setprecision(2) << r.duration << " s";
          if (!r.reason.empty()) std::cout << "  (" << r.reason << ")";
          std::cout << "\n";
        };
        const sim::SessionReport rep = session.run(actions, print_action);
        if (use_camera) {
          sim::CameraRig rig(session.sim(), cameras, a->seed);
          sim::write_camera_snapshot(rig, rig.index(camera_name, {}), session.sim(),
                                     {a->snapshot, a->depth, a->segmentation});
        } else if (!a->snapshot.empty()) {
          session.snapshot(a->snapshot);
        }
        int failures = 0;
        for (const auto& r : rep.actions) failures += r.status != sim::Status::Success;
        if (a->json) {
          nlohmann::json j;
          j["scenario"] = scenario.name;
          j["seed"] = a->seed;
          j["actions"] = nlohmann::json::array();
          for (const auto& r : rep.actions)
            j["actions"].push_back({{"action", r.action},
                                    {"outcome", sim::to_string(r.status)},
                                    {"reason", r.reason},
                                    {"cost", r.cost},
                                    {"start", r.start},
                                    {"sim_time", r.duration}});
          j["interventions"] = nlohmann::json::array();
          for (const auto& e : rep.interventions)
            j["interventions"].push_back(
                {{"time", e.time}, {"subject", e.what.subject}, {"applied", e.applied}, {"detail", e.detail}});
          nlohmann::json where = nlohmann::json::object();
          for (const auto& o : rep.final_percept.things)
            where[o.name] = {{"location", o.detected ? o.location : std::string("undetected")},
                             {"class", o.cls},
                             {"position", {o.position[0], o.position[1], o.position[2]}}};
          if (const sim::CameraPerception* eyes = session.perception().camera())
            for (const auto& t : eyes->belief().things()) where[t.name]["state"] = world::to_string(t.state);
          j["perception"] = a->perception;
          j["perceived"] = where;
          j["sim_time"] = rep.sim_time;
          j["wall_time"] = rep.wall_time;
          j["real_time_factor"] = rep.real_time_factor();
          nlohmann::json w = nlohmann::json::object();
          for (int i = 0; i < mjNWARNING; ++i) w[sim::Warnings::name(i)] = rep.warnings.count[i];
          j["mujoco_warnings"] = w;
          if (!a->video.empty()) j["video_frames"] = rep.video_frames;
          std::cout << j.dump(2) << "\n";
        } else {
          std::cout << "perceived:";
          for (const auto& o : rep.final_percept.things)
            std::cout << ' ' << o.name << '=' << (o.detected ? o.location : std::string("undetected"));
          std::cout << "\n";
          for (const auto& e : rep.interventions)
            std::cout << "operator at " << std::setprecision(2) << e.time << " s: " << e.what.subject << " "
                      << (e.applied ? "" : "refused: ") << e.detail << "\n";
          std::cout << "simulated " << std::setprecision(2) << rep.sim_time << " s in " << std::setprecision(3)
                    << rep.wall_time << " s wall: " << std::setprecision(1) << rep.real_time_factor()
                    << "x real time\n";
          if (rep.warnings.total() > 0) {
            std::cout << "MuJoCo warnings:";
            for (int i = 0; i < mjNWARNING; ++i)
              if (rep.warnings.count[i]) std::cout << ' ' << sim::Warnings::name(i) << '=' << rep.warnings.count[i];
            std::cout << "\n";
          }
        }
        return failures == 0 ? 0 : 1;
      };
    }};

}  // namespace
