// Segmentation of an RGB image by the known colours of a scene (the paper's way: things
// are told apart by colour). Each pixel takes the known colour nearest in hue — the
// direction of its chroma vector, the colour minus its smallest channel, which shading
// scales and white light (ambient, specular, clipping) leaves alone — or none when that
// angle exceeds max_angle_deg or the pixel is too grey or dark to tell; then
// each thing colour's mask is opened (OpenCV 4) to drop specks and split into connected
// blobs. Only the pixels are used, never the simulator's segmentation pass (tests score
// against that).
//
// Invariants: the classification is a lookup table over RGB quantised to 6 bits a channel,
// built once; a blob's pixels all carry its colour's label; blobs smaller than
// min_blob_pixels are dropped and their pixels labelled none. The opening and the blobs
// are computed inside each thing colour's bounding box (grown by the opening's radius),
// which gives exactly the whole image's result at a fraction of its cost.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

struct KnownColour {
  std::string label;            // a thing class ("block"), or what else shows it ("region r1", "table", "arm")
  std::array<double, 3> rgb{};  // in [0, 1], as modelled (unlit)
  bool thing = false;           // things of a class: blobs are made of these only
};

struct ColourSegmentationOptions {
  double max_angle_deg = 6.0;  // farther from every known colour: none
  int min_chroma = 24;         // a pixel whose channels differ by less (grey, dark): none
  double min_saturation = 0.2;  // a pixel whose chroma is less than this part of its largest channel
                                // (washed out: a pale surface clipped at 255 turns its hue): none
  int min_blob_pixels = 12;    // smaller blobs are dropped
  int opening_radius = 1;      // of the square opening applied to each thing colour's mask (0: none)
};

struct ColourBlob {
  std::size_t colour = 0;          // index into the segmenter's colours
  std::vector<std::int32_t> pixels;  // row-major indices, ascending
};

struct ColourSegmentation {
  int width = 0, height = 0;
  std::vector<std::int16_t> label;  // per pixel: index of a known colour, -1 none
  std::vector<ColourBlob> blobs;    // thing colours only

  // The segmenter's working storage, kept between frames.
  std::vector<std::array<int, 4>> boxes_;  // each colour's pixels' bounding box
  std::vector<std::uint8_t> mask_;
  std::vector<std::int32_t> components_;
};

class ColourSegmenter {
 public:
  // Throws rtamp::Error on an empty palette or options out of range.
  explicit ColourSegmenter(std::vector<KnownColour> colours, ColourSegmentationOptions options = {});
  const std::vector<KnownColour>& colours() const { return colours_; }
  // rgb: width x height x 3 bytes, top row first.
  void segment(const std::uint8_t* rgb, int width, int height, ColourSegmentation& out) const;

 private:
  std::vector<KnownColour> colours_;
  ColourSegmentationOptions options_;
  std::vector<std::int16_t> table_;  // 64^3 entries
  std::vector<std::uint8_t> thing_;  // colours_[k].thing
};

// Refuses, as rtamp::Error at the class's `colours:` entry (else its first thing or the
// operator action that adds it), a thing class of `s` (scene_colours) whose colour has no
// hue to find it by, or whose hue lies within 2 max_angle_deg of another thing class's:
// their acceptance cones meet, so shading or noise could give one's pixels to the other.
void check_scene_colours(const world::Scenario& s, const ColourSegmentationOptions& options = {});

// The colours a MuJoCo model built from `s` shows (mjcf_builder.hpp): each thing class,
// each region's fill and outline, the table, the floor, the arm and the gripper.
std::vector<KnownColour> scene_colours(const world::Scenario& s);
// scene_colours without the thing classes: the regions', the table's, the arm's.
std::vector<KnownColour> backdrop_colours(const world::Scenario& s);

// The angle between two colours' hues as the segmentation measures it (the directions of
// their chroma vectors), in degrees in [0, 90]; 0 if either has no chroma.
double hue_angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b);
// A colour's chroma: its largest channel minus its smallest.
double chroma_span(const std::array<double, 3>& c);

}  // namespace rtamp::sim
