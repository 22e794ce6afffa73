#include "solver/simulation/checkpoint.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "formats/json_file.hpp"

namespace rbcal::solver {

namespace {

// Version 2 added the indicator positions (and numerics.indicator_tolerance to the case),
// version 3 the velocity summed over a coupling interval (numerics.node_velocity),
// version 4 a checksum of everything before it, so that a damaged file is refused instead
// of resumed into a different result.
constexpr char kMagic[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '4'};
constexpr char kMagicV3[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '3'};
constexpr char kMagicV2[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '2'};
constexpr char kMagicV1[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '1'};

// A 64-bit checksum fed in pieces of any length: FNV-1a's step on 8-byte words (bytes
// gathered across pieces), which catches overwritten or shifted bytes at memory speed.
class Checksum {
 public:
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n;) {
      if (pending_ == 0 && n - i >= 8) {
        std::uint64_t word;
        std::memcpy(&word, data + i, 8);
        mix(word);
        i += 8;
        continue;
      }
      buffer_[pending_++] = data[i++];
      if (pending_ == 8) {
        std::uint64_t word;
        std::memcpy(&word, buffer_, 8);
        mix(word);
        pending_ = 0;
      }
    }
  }
  std::uint64_t value() const {
    std::uint64_t h = hash_;
    for (int k = 0; k < pending_; ++k) h = (h ^ static_cast<unsigned char>(buffer_[k])) * kPrime;
    return h ^ (h >> 29);
  }

 private:
  static constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  void mix(std::uint64_t word) { hash_ = (hash_ ^ word) * kPrime; }
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
  char buffer_[8] = {};
  int pending_ = 0;
};

class Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out) {}
  void u64(std::uint64_t v) { out_.write(reinterpret_cast<const char*>(&v), sizeof v); }
  void doubles(const double* d, std::size_t n) {
    u64(n);
    out_.write(reinterpret_cast<const char*>(d), static_cast<std::streamsize>(n * sizeof(double)));
  }
  void cells(const std::vector<std::vector<Vec3>>& c) {
    u64(c.size());
    for (const auto& cell : c) doubles(cell.empty() ? nullptr : cell[0].data(), 3 * cell.size());
  }

 private:
  std::ostream& out_;
};

class Reader {
 public:
  Reader(std::ifstream& in, std::string path) : in_(in), path_(std::move(path)) {}
  // Reads n bytes into d, adding them to the checksum.
  void bytes(char* d, std::size_t n) {
    in_.read(d, static_cast<std::streamsize>(n));
    check();
    sum_.add(d, n);
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    bytes(reinterpret_cast<char*>(&v), sizeof v);
    return v;
  }
  std::uint64_t checksum() const { return sum_.value(); }
  void add_to_checksum(const char* d, std::size_t n) { sum_.add(d, n); }  // bytes read elsewhere
  std::vector<double> doubles() {
    const std::uint64_t n = u64();
    if (n > (std::uint64_t{1} << 36)) fail("implausible array length");
    std::vector<double> d(n);
    bytes(reinterpret_cast<char*>(d.data()), n * sizeof(double));
    return d;
  }
  std::vector<std::vector<Vec3>> cells() {
    const std::uint64_t count = u64();
    std::vector<std::vector<Vec3>> c(count);
    for (auto& cell : c) {
      const std::vector<double> d = doubles();
      if (d.size() % 3) fail("cell array is not a list of 3-vectors");
      for (std::size_t i = 0; i < d.size(); i += 3) cell.emplace_back(d[i], d[i + 1], d[i + 2]);
    }
    return c;
  }
  [[noreturn]] void fail(const std::string& what) { throw std::runtime_error("checkpoint " + path_ + ": " + what); }

 private:
  void check() {
    if (!in_) fail("truncated");
  }
  std::ifstream& in_;
  std::string path_;
  Checksum sum_;
};

}  // namespace

void write_checkpoint(const std::string& path, const CheckpointState& s) {
  // Built in memory, then written through a temporary file and a rename: a run killed
  // while writing keeps its previous checkpoint.
  std::ostringstream out(std::ios::binary);
  out.write(kMagic, sizeof kMagic);
  Writer w(out);
  w.u64(s.case_json.size());
  out.write(s.case_json.data(), static_cast<std::streamsize>(s.case_json.size()));
  w.u64(static_cast<std::uint64_t>(s.steps));
  w.doubles(s.populations.data(), s.populations.size());
  w.cells(s.positions);
  w.cells(s.velocities);
  w.cells(s.forces);
  w.cells(s.indicator_positions);
  w.doubles(s.velocity_sum.data(), s.velocity_sum.size());
  w.u64(s.velocity_sum_steps);
  Checksum sum;
  const std::string body = out.str();
  sum.add(body.data(), body.size());
  w.u64(sum.value());
  out.write(kMagic, sizeof kMagic);  // end marker: a complete file
  formats::write_file_atomically(path, out.str());
}

CheckpointState read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open checkpoint " + path);
  Reader r(in, path);
  char magic[8];
  in.read(magic, sizeof magic);
  if (in && std::equal(magic, magic + 8, kMagicV1))
    r.fail("format 1, written by an older rbcal; remove it to run the case from its start");
  if (!in) r.fail("not an rbcal checkpoint");
  const int version = std::equal(magic, magic + 8, kMagic) ? 4 : std::equal(magic, magic + 8, kMagicV3) ? 3
                      : std::equal(magic, magic + 8, kMagicV2)                                       ? 2
                                                                                                     : 0;
  if (version == 0) r.fail("not an rbcal checkpoint");
  r.add_to_checksum(magic, sizeof magic);  // the checksum covers the leading magic too
  CheckpointState s;
  const std::uint64_t json_size = r.u64();
  if (json_size > (1u << 26)) r.fail("implausible case size");
  s.case_json.resize(json_size);
  r.bytes(s.case_json.data(), json_size);
  s.steps = static_cast<std::int64_t>(r.u64());
  s.populations = r.doubles();
  s.positions = r.cells();
  s.velocities = r.cells();
  s.forces = r.cells();
  s.indicator_positions = r.cells();
  if (version >= 3) {
    s.velocity_sum = r.doubles();
    s.velocity_sum_steps = r.u64();
  }
  if (version >= 4) {
    const std::uint64_t computed = r.checksum();
    std::uint64_t stored = 0;
    in.read(reinterpret_cast<char*>(&stored), sizeof stored);
    if (!in) r.fail("truncated (no checksum)");
    if (stored != computed) r.fail("damaged: its checksum does not match its contents; resume from an intact copy or "
                                   "remove it to run the case from its start");
  }
  in.read(magic, sizeof magic);
  const char* end = version == 4 ? kMagic : version == 3 ? kMagicV3 : kMagicV2;
  if (!in || !std::equal(magic, magic + 8, end)) r.fail("truncated (no end marker)");
  return s;
}

}  // namespace rbcal::solver
