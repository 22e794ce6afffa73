#include "solver/simulation/checkpoint.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "formats/json_file.hpp"

namespace rbcal::solver {

namespace {

// Version 2 added the indicator positions (and numerics.indicator_tolerance to the case),
// version 3 the velocity summed over a coupling interval (numerics.node_velocity).
constexpr char kMagic[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '3'};
constexpr char kMagicV2[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '2'};
constexpr char kMagicV1[8] = {'R', 'B', 'C', 'A', 'L', 'C', 'K', '1'};

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
  std::uint64_t u64() {
    std::uint64_t v = 0;
    in_.read(reinterpret_cast<char*>(&v), sizeof v);
    check();
    return v;
  }
  std::vector<double> doubles() {
    const std::uint64_t n = u64();
    if (n > (std::uint64_t{1} << 36)) fail("implausible array length");
    std::vector<double> d(n);
    in_.read(reinterpret_cast<char*>(d.data()), static_cast<std::streamsize>(n * sizeof(double)));
    check();
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
  const bool version2 = in && std::equal(magic, magic + 8, kMagicV2);
  if (!in || !(version2 || std::equal(magic, magic + 8, kMagic))) r.fail("not an rbcal checkpoint");
  CheckpointState s;
  const std::uint64_t json_size = r.u64();
  if (json_size > (1u << 26)) r.fail("implausible case size");
  s.case_json.resize(json_size);
  in.read(s.case_json.data(), static_cast<std::streamsize>(json_size));
  s.steps = static_cast<std::int64_t>(r.u64());
  s.populations = r.doubles();
  s.positions = r.cells();
  s.velocities = r.cells();
  s.forces = r.cells();
  s.indicator_positions = r.cells();
  if (!version2) {
    s.velocity_sum = r.doubles();
    s.velocity_sum_steps = r.u64();
  }
  in.read(magic, sizeof magic);
  if (!in || !std::equal(magic, magic + 8, version2 ? kMagicV2 : kMagic)) r.fail("truncated (no end marker)");
  return s;
}

}  // namespace rbcal::solver
