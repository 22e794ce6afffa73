#include "solver/io/detail/vtk_writer.hpp"

#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "solver/fluid/fluid_lattice.hpp"

namespace rbcal::solver {

namespace {

std::ofstream open_or_throw(const std::string& path, std::ios::openmode mode = std::ios::out) {
  std::ofstream out(path, mode);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

}  // namespace

void write_membranes_vtp(const std::string& path, const VtkMeshes& m) {
  std::ofstream out = open_or_throw(path);
  const auto& cells = *m.positions;
  const auto& tri = *m.triangles;
  std::size_t points = 0;
  for (const auto& c : cells) points += c.size();
  const std::size_t polys = tri.size() * cells.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << points << "\" NumberOfPolys=\"" << polys << "\">\n";
  auto vectors = [&](const char* name, const std::vector<std::vector<Vec3>>& data) {
    out << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& c : data)
      for (const Vec3& v : c) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    out << "</DataArray>\n";
  };
  out << "<PointData Vectors=\"velocity\">\n";
  vectors("velocity", *m.velocities);
  vectors("force", *m.forces);
  out << "<DataArray type=\"Int32\" Name=\"cell\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t i = 0; i < cells[c].size(); ++i) out << c << '\n';
  out << "</DataArray>\n</PointData>\n<Points>\n";
  vectors("points", cells);
  out << "</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  std::size_t base = 0;
  for (const auto& c : cells) {
    for (const Triangle& t : tri) out << base + t[0] << ' ' << base + t[1] << ' ' << base + t[2] << '\n';
    base += c.size();
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t p = 1; p <= polys; ++p) out << 3 * p << '\n';
  out << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

void write_fluid_vti(const std::string& path, const FluidLattice& fluid, const std::vector<double>* alpha) {
  std::ofstream out = open_or_throw(path, std::ios::out | std::ios::binary);
  const std::size_t n = fluid.node_count();
  // VTK ImageData is x-fastest; the lattice is z-fastest, so points are reordered.
  std::vector<double> velocity(3 * n), density(n), inside;
  std::size_t p = 0;
  for (int z = 0; z < fluid.nz(); ++z)
    for (int y = 0; y < fluid.ny(); ++y)
      for (int x = 0; x < fluid.nx(); ++x, ++p) {
        const std::size_t node = fluid.index(x, y, z);
        const NodeMoments m = fluid.moments(node);
        velocity[3 * p] = m.ux;
        velocity[3 * p + 1] = m.uy;
        velocity[3 * p + 2] = m.uz;
        density[p] = m.rho;
        if (alpha) inside.push_back((*alpha)[node]);
      }
  const std::uint64_t vbytes = velocity.size() * 8, dbytes = density.size() * 8, abytes = inside.size() * 8;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<ImageData WholeExtent=\"0 "
      << fluid.nx() - 1 << " 0 " << fluid.ny() - 1 << " 0 " << fluid.nz() - 1
      << "\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n<Piece Extent=\"0 " << fluid.nx() - 1 << " 0 " << fluid.ny() - 1
      << " 0 " << fluid.nz() - 1 << "\">\n<PointData Vectors=\"velocity\" Scalars=\"density\">\n"
      << "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>\n"
      << "<DataArray type=\"Float64\" Name=\"density\" format=\"appended\" offset=\"" << 8 + vbytes << "\"/>\n";
  if (alpha)
    out << "<DataArray type=\"Float64\" Name=\"inside_fraction\" format=\"appended\" offset=\"" << 16 + vbytes + dbytes
        << "\"/>\n";
  out << "</PointData>\n</Piece>\n</ImageData>\n<AppendedData encoding=\"raw\">\n_";
  auto block = [&](const std::vector<double>& v, std::uint64_t bytes) {
    out.write(reinterpret_cast<const char*>(&bytes), 8);
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(bytes));
  };
  block(velocity, vbytes);
  block(density, dbytes);
  if (alpha) block(inside, abytes);
  out << "\n</AppendedData>\n</VTKFile>\n";
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries) {
  std::ofstream out = open_or_throw(path);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : entries) out << "<DataSet timestep=\"" << t << "\" file=\"" << file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
}

}  // namespace rbcal::solver
