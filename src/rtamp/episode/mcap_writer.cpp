#include "rtamp/episode/mcap_writer.hpp"

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <tuple>

#include "rtamp/util/error.hpp"

namespace rtamp::episode {

namespace {

constexpr char kMagic[] = "\x89MCAP0\r\n";
constexpr std::size_t kMagicSize = 8;

enum Op : std::uint8_t {
  Header = 0x01,
  Footer = 0x02,
  SchemaOp = 0x03,
  ChannelOp = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndexOp = 0x08,
  Statistics = 0x0B,
  MetadataOp = 0x0C,
  MetadataIndexOp = 0x0D,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

// Little-endian primitives of the specification.
void u8(std::string& b, std::uint8_t v) { b += static_cast<char>(v); }
template <typename T>
void le(std::string& b, T v) {
  for (std::size_t i = 0; i < sizeof(T); ++i) b += static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * i)) & 0xff);
}
void str(std::string& b, std::string_view s) {
  le<std::uint32_t>(b, static_cast<std::uint32_t>(s.size()));
  b.append(s);
}
// opcode, u64 content length, content.
void record(std::string& b, std::uint8_t op, const std::string& content) {
  u8(b, op);
  le<std::uint64_t>(b, content.size());
  b += content;
}

std::uint32_t crc(std::uint32_t c, const std::string& bytes) {
  return static_cast<std::uint32_t>(
      crc32_z(c, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

const char* name_of(McapCompression c) {
  switch (c) {
    case McapCompression::Zstd: return "zstd";
    case McapCompression::Lz4: return "lz4";
    case McapCompression::None: break;
  }
  return "";
}

std::string schema_record(const std::uint16_t id, const std::string& name, const std::string& encoding,
                          const std::string& data) {
  std::string c;
  le<std::uint16_t>(c, id);
  str(c, name);
  str(c, encoding);
  str(c, data);
  std::string r;
  record(r, SchemaOp, c);
  return r;
}

// Map<string, string>: its byte length, then key and value of each pair (in key order).
void string_map(std::string& b, const std::map<std::string, std::string>& m) {
  std::string pairs;
  for (const auto& [k, v] : m) {
    str(pairs, k);
    str(pairs, v);
  }
  le<std::uint32_t>(b, static_cast<std::uint32_t>(pairs.size()));
  b += pairs;
}

std::string channel_record(std::uint16_t id, std::uint16_t schema, const std::string& topic,
                           const std::string& encoding, const std::map<std::string, std::string>& metadata) {
  std::string c;
  le<std::uint16_t>(c, id);
  le<std::uint16_t>(c, schema);
  str(c, topic);
  str(c, encoding);
  string_map(c, metadata);
  std::string r;
  record(r, ChannelOp, c);
  return r;
}

}  // namespace

McapCompression parse_mcap_compression(const std::string& text) {
  if (text == "zstd") return McapCompression::Zstd;
  if (text == "lz4") return McapCompression::Lz4;
  if (text == "none") return McapCompression::None;
  throw Error("unknown MCAP compression '" + text + "' (zstd, lz4 or none)");
}

McapWriter::McapWriter(const std::string& path, McapCompression compression, std::size_t chunk_bytes,
                       const std::string& what, const std::string& profile, const std::string& library)
    : out_(path, what), path_(path), compression_(compression), chunk_bytes_(chunk_bytes) {
  std::string b(kMagic, kMagicSize);
  std::string h;
  str(h, profile);  // "": none of the well-known ones (JSON messages with JSON schemas)
  str(h, library);
  record(b, Header, h);
  emit_data(b);
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (...) {  // a destructor must not throw; close() explicitly to see errors
  }
}

void McapWriter::emit(const std::string& bytes) {
  if (!lost_.empty()) throw OutputError(lost_);  // the file stopped at the first lost write
  try {
    out_.write(bytes);  // OutputError naming the file and why
  } catch (const OutputError& e) {
    lost_ = e.message();
    throw;
  }
  offset_ += bytes.size();
}

void McapWriter::emit_data(const std::string& bytes) {
  data_crc_ = crc(data_crc_, bytes);
  emit(bytes);
}

std::uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, name, encoding, data});
  chunk_ += schema_record(id, name, encoding, data);
  return id;
}

std::uint16_t McapWriter::add_channel(const std::string& topic, std::uint16_t schema_id,
                                      const std::string& message_encoding,
                                      const std::map<std::string, std::string>& metadata) {
  const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
  channels_.push_back({id, schema_id, topic, message_encoding, metadata});
  chunk_ += channel_record(id, schema_id, topic, message_encoding, metadata);
  return id;
}

void McapWriter::add_metadata(const std::string& name, const std::map<std::string, std::string>& values) {
  flush_chunk();  // a Metadata record stands between chunks
  std::string c;
  str(c, name);
  string_map(c, values);
  std::string r;
  record(r, MetadataOp, c);
  metadata_indexes_.push_back({offset_, r.size(), name});
  emit_data(r);
}

void McapWriter::write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time,
                       std::string_view data) {
  if (!chunk_has_messages_) {
    chunk_start_ = chunk_end_ = log_time;
    chunk_has_messages_ = true;
  }
  chunk_start_ = std::min(chunk_start_, log_time);
  chunk_end_ = std::max(chunk_end_, log_time);
  if (message_count_ == 0) first_time_ = last_time_ = log_time;
  first_time_ = std::min(first_time_, log_time);
  last_time_ = std::max(last_time_, log_time);
  const std::uint32_t sequence = static_cast<std::uint32_t>(channel_counts_[channel]++);
  ++message_count_;

  chunk_index_[channel].emplace_back(log_time, chunk_.size());
  // The record's 31 header bytes at once (the most frequent record).
  char head[31];
  std::size_t at = 0;
  const auto put = [&](std::uint64_t v, std::size_t bytes) {
    for (std::size_t i = 0; i < bytes; ++i) head[at++] = static_cast<char>((v >> (8 * i)) & 0xff);
  };
  put(Message, 1);
  put(2 + 4 + 8 + 8 + data.size(), 8);
  put(channel, 2);
  put(sequence, 4);
  put(log_time, 8);
  put(publish_time, 8);
  chunk_.append(head, sizeof head);
  chunk_.append(data);
  if (chunk_.size() >= chunk_bytes_) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  const std::string* body = &chunk_;
  if (compression_ == McapCompression::Zstd) {
    compressed_.resize(ZSTD_compressBound(chunk_.size()));
    const std::size_t n = ZSTD_compress(compressed_.data(), compressed_.size(), chunk_.data(), chunk_.size(), 1);
    if (ZSTD_isError(n)) throw Error("MCAP file '" + path_ + "': zstd: " + ZSTD_getErrorName(n));
    compressed_.resize(n);
    body = &compressed_;
  } else if (compression_ == McapCompression::Lz4) {
    LZ4F_preferences_t prefs{};
    prefs.frameInfo.contentSize = chunk_.size();
    compressed_.resize(LZ4F_compressFrameBound(chunk_.size(), &prefs));
    const std::size_t n = LZ4F_compressFrame(compressed_.data(), compressed_.size(), chunk_.data(), chunk_.size(), &prefs);
    if (LZ4F_isError(n)) throw Error("MCAP file '" + path_ + "': lz4: " + LZ4F_getErrorName(n));
    compressed_.resize(n);
    body = &compressed_;
  }

  ChunkIndex ci;
  ci.start = chunk_has_messages_ ? chunk_start_ : 0;
  ci.end = chunk_has_messages_ ? chunk_end_ : 0;
  ci.offset = offset_;
  ci.compressed = body->size();
  ci.uncompressed = chunk_.size();

  std::string c;
  le<std::uint64_t>(c, ci.start);
  le<std::uint64_t>(c, ci.end);
  le<std::uint64_t>(c, chunk_.size());
  le<std::uint32_t>(c, crc(0, chunk_));
  str(c, name_of(compression_));
  le<std::uint64_t>(c, body->size());
  c += *body;
  std::string r;
  record(r, Chunk, c);
  ci.length = r.size();
  std::string indexes;
  for (const auto& [channel, entries] : chunk_index_) {
    ci.index_offsets.emplace_back(channel, offset_ + r.size() + indexes.size());
    std::string m;
    le<std::uint16_t>(m, channel);
    le<std::uint32_t>(m, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, at] : entries) {
      le<std::uint64_t>(m, time);
      le<std::uint64_t>(m, at);
    }
    record(indexes, MessageIndex, m);
  }
  ci.index_length = indexes.size();
  r += indexes;
  emit_data(r);
  chunk_indexes_.push_back(std::move(ci));

  chunk_.clear();
  chunk_index_.clear();
  chunk_has_messages_ = false;
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  if (!lost_.empty()) throw OutputError(lost_);
  flush_chunk();
  std::string end;
  std::string c;
  le<std::uint32_t>(c, data_crc_);
  record(end, DataEnd, c);
  emit(end);  // the data section ends here: the data CRC covers everything before DataEnd
  write_summary();
  out_.close();
}

void McapWriter::write_summary() {
  const std::uint64_t summary_start = offset_;
  std::string s;
  // Groups of the summary, each recorded by a SummaryOffset record.
  std::vector<std::tuple<std::uint8_t, std::uint64_t, std::uint64_t>> groups;
  auto group = [&](std::uint8_t op, const std::string& bytes) {
    if (bytes.empty()) return;
    groups.emplace_back(op, summary_start + s.size(), bytes.size());
    s += bytes;
  };
  std::string g;
  for (const auto& x : schemas_) g += schema_record(x.id, x.name, x.encoding, x.data);
  group(SchemaOp, g);
  g.clear();
  for (const auto& x : channels_) g += channel_record(x.id, x.schema, x.topic, x.encoding, x.metadata);
  group(ChannelOp, g);
  g.clear();
  {
    std::string c;
    le<std::uint64_t>(c, message_count_);
    le<std::uint16_t>(c, static_cast<std::uint16_t>(schemas_.size()));
    le<std::uint32_t>(c, static_cast<std::uint32_t>(channels_.size()));
    le<std::uint32_t>(c, 0);  // attachments
    le<std::uint32_t>(c, static_cast<std::uint32_t>(metadata_indexes_.size()));
    le<std::uint32_t>(c, static_cast<std::uint32_t>(chunk_indexes_.size()));
    le<std::uint64_t>(c, first_time_);
    le<std::uint64_t>(c, last_time_);
    le<std::uint32_t>(c, static_cast<std::uint32_t>(channel_counts_.size() * 10));
    for (const auto& [channel, n] : channel_counts_) {
      le<std::uint16_t>(c, channel);
      le<std::uint64_t>(c, n);
    }
    record(g, Statistics, c);
  }
  group(Statistics, g);
  g.clear();
  for (const auto& m : metadata_indexes_) {
    std::string c;
    le<std::uint64_t>(c, m.offset);
    le<std::uint64_t>(c, m.length);
    str(c, m.name);
    record(g, MetadataIndexOp, c);
  }
  group(MetadataIndexOp, g);
  g.clear();
  for (const auto& ci : chunk_indexes_) {
    std::string c;
    le<std::uint64_t>(c, ci.start);
    le<std::uint64_t>(c, ci.end);
    le<std::uint64_t>(c, ci.offset);
    le<std::uint64_t>(c, ci.length);
    le<std::uint32_t>(c, static_cast<std::uint32_t>(ci.index_offsets.size() * 10));
    for (const auto& [channel, at] : ci.index_offsets) {
      le<std::uint16_t>(c, channel);
      le<std::uint64_t>(c, at);
    }
    le<std::uint64_t>(c, ci.index_length);
    str(c, name_of(compression_));
    le<std::uint64_t>(c, ci.compressed);
    le<std::uint64_t>(c, ci.uncompressed);
    record(g, ChunkIndexOp, c);
  }
  group(ChunkIndexOp, g);

  const std::uint64_t offsets_start = summary_start + s.size();
  for (const auto& [op, start, length] : groups) {
    std::string c;
    u8(c, op);
    le<std::uint64_t>(c, start);
    le<std::uint64_t>(c, length);
    record(s, SummaryOffset, c);
  }
  // Footer: the summary CRC covers the summary, the offsets and the footer up to its CRC field.
  u8(s, Footer);
  le<std::uint64_t>(s, 8 + 8 + 4);
  le<std::uint64_t>(s, summary_start);
  le<std::uint64_t>(s, offsets_start);
  le<std::uint32_t>(s, crc(0, s));
  s.append(kMagic, kMagicSize);
  emit(s);
}

}  // namespace rtamp::episode
