// A writer of MCAP files (mcap.dev/spec, format version 0), written from the
// public specification: magic, Header, a data section of Chunks (each with the
// uncompressed records' CRC32, compressed with zstd or lz4 (frame format) or
// not at all) each followed by its MessageIndex records, Metadata records
// between chunks, DataEnd with the data section's CRC32, then a summary section
// (Schema, Channel, Statistics, MetadataIndex and ChunkIndex records, with
// SummaryOffset records for each group) and a Footer carrying the summary's
// CRC32 — what viewers need to seek. The Header names the profile ("" for
// rtamp's JSON channels, "ros2" for CDR ones) and the library that wrote it.
// Invariants: a Schema and a Channel record are in the data section before
// the first message that uses them; every chunk's message indexes list its
// messages per channel in the order written, with offsets into the
// uncompressed chunk; the file is valid only after close() (the destructor
// closes, quietly). The file is an OutputFile (util/output_file.hpp: locked
// while written, every write checked); errors writing or compressing throw
// rtamp::Error (rtamp::OutputError for a lost write) naming the file.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rtamp/util/output_file.hpp"

namespace rtamp::episode {

enum class McapCompression { None, Zstd, Lz4 };

// "none", "zstd", "lz4"; rtamp::Error for anything else.
McapCompression parse_mcap_compression(const std::string& text);

class McapWriter {
 public:
  // Opens `path` (rtamp::Error if it cannot be written). Chunks are closed when
  // their uncompressed records reach `chunk_bytes`. `what` names the file in errors;
  // `profile` and `library` go into the Header record.
  explicit McapWriter(const std::string& path, McapCompression compression = McapCompression::Zstd,
                      std::size_t chunk_bytes = 1 << 20, const std::string& what = "--mcap",
                      const std::string& profile = "", const std::string& library = "rtamp");
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Ids start at 1; `data` is the schema text (e.g. a JSON Schema, encoding "jsonschema").
  std::uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  // `metadata`: the channel's key/value pairs (the ros2 profile's offered_qos_profiles).
  std::uint16_t add_channel(const std::string& topic, std::uint16_t schema_id, const std::string& message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  // A Metadata record (between chunks: the open chunk is closed first), indexed in the summary.
  void add_metadata(const std::string& name, const std::map<std::string, std::string>& values);
  // One message; times in nanoseconds.
  void write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time, std::string_view data);
  // Writes the last chunk, the summary and the footer; idempotent.
  void close();
  // Closes the file quietly and removes it if it is a regular file (a failed conversion).
  void discard() noexcept {
    closed_ = true;
    out_.discard();
  }

  std::uint64_t message_count() const { return message_count_; }
  const std::string& path() const { return path_; }

 private:
  struct Schema {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    std::uint16_t id, schema;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  struct MetadataIndex {
    std::uint64_t offset = 0, length = 0;
    std::string name;
  };
  struct ChunkIndex {
    std::uint64_t start = 0, end = 0, offset = 0, length = 0, index_length = 0, compressed = 0,
                  uncompressed = 0;
    std::vector<std::pair<std::uint16_t, std::uint64_t>> index_offsets;
  };

  void emit(const std::string& bytes);       // to the file, keeping the offset
  void emit_data(const std::string& bytes);  // the same, in the data section (its CRC)
  void flush_chunk();
  void write_summary();

  OutputFile out_;
  std::string lost_;  // the first lost write (then nothing more is written)
  std::string path_;
  McapCompression compression_;
  std::size_t chunk_bytes_;
  bool closed_ = false;
  std::uint64_t offset_ = 0;
  std::uint32_t data_crc_ = 0;

  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<ChunkIndex> chunk_indexes_;
  std::vector<MetadataIndex> metadata_indexes_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;

  // The open chunk.
  std::string chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  bool chunk_has_messages_ = false;
  std::string compressed_;
};

}  // namespace rtamp::episode
