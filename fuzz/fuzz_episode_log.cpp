// libFuzzer target for the episode-log reader (episode/log_check.hpp, the one
// check of `serve --replay` and `log to-mcap`) and the MCAP converter behind
// it (episode_mcap.hpp): any input, taken as a log's lines, must either pass
// the check or raise rtamp::Error — no crash, hang, leak or other exception;
// the bounded line reader must refuse lines beyond its limit; and every log
// that passes must convert to MCAP without an error (the check lets through
// only what the converter can take).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/episode/log_check.hpp"
#include "rtamp/util/error.hpp"

namespace {

// A private file for the fuzzer's log and its MCAP (never a device of the system).
std::string scratch_path(const char* tail) {
  static const std::string dir = [] {
    char tmpl[] = "/tmp/fuzz_episode_log_XXXXXX";
    const char* d = ::mkdtemp(tmpl);
    if (!d) std::abort();
    return std::string(d);
  }();
  return dir + "/" + tail;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string log = scratch_path("log.jsonl"), mcap = scratch_path("log.mcap");
  std::ofstream(log, std::ios::binary | std::ios::trunc)
      .write(text.data(), static_cast<std::streamsize>(text.size()));
  bool passed = false;
  try {
    rtamp::episode::read_episode_log(log, nullptr);
    passed = true;
  } catch (const rtamp::Error&) {
  }
  if (passed) {
    try {
      rtamp::episode::log_to_mcap(log, mcap, rtamp::episode::McapCompression::None);
    } catch (const rtamp::Error&) {
      std::abort();  // a log the check passed that the converter refuses
    }
  }
  return 0;
}
