#include "common/study/vtu.hpp"

#include "common/fem/p2_elasticity.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace mortar {

namespace {
const char* type_name(double) { return "Float64"; }
const char* type_name(std::int32_t) { return "Int32"; }
const char* type_name(std::uint8_t) { return "UInt8"; }

// base64 of a UInt32 byte count followed by the bytes of the values (the machine is
// little-endian on every platform the course builds on; byte_order says so).
template <class T>
void write_base64(std::ostream& f, const std::vector<T>& values) {
  static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::uint32_t count = static_cast<std::uint32_t>(values.size() * sizeof(T));
  std::vector<unsigned char> bytes(sizeof count + count);
  std::memcpy(bytes.data(), &count, sizeof count);
  if (count > 0) std::memcpy(bytes.data() + sizeof count, values.data(), count);
  std::string out;
  out.reserve(4 * (bytes.size() + 2) / 3);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const std::uint32_t b = (std::uint32_t(bytes[i]) << 16) | (left > 1 ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                            (left > 2 ? std::uint32_t(bytes[i + 2]) : 0);
    out += table[(b >> 18) & 63];
    out += table[(b >> 12) & 63];
    out += left > 1 ? table[(b >> 6) & 63] : '=';
    out += left > 2 ? table[b & 63] : '=';
  }
  f << out << "\n";
}

template <class T>
void write_array(std::ostream& f, const std::string& attributes, const std::vector<T>& values, int per_line,
                 VtuFormat format) {
  f << "<DataArray type=\"" << type_name(T{}) << "\" " << attributes << " format=\""
    << (format == VtuFormat::binary ? "binary" : "ascii") << "\">\n";
  if (format == VtuFormat::binary) {
    write_base64(f, values);
  } else {
    for (std::size_t i = 0; i < values.size(); ++i)
      f << +values[i] << ((i + 1) % per_line == 0 || i + 1 == values.size() ? "\n" : " ");
  }
  f << "</DataArray>\n";
}

void write_data(std::ostream& f, const char* tag, const std::vector<VtuArray>& arrays, std::size_t count,
                VtuFormat format) {
  f << "<" << tag << ">\n";
  for (const VtuArray& a : arrays) {
    if (a.components < 1 || a.values.size() != count * a.components)
      throw std::invalid_argument("write_vtu: array " + a.name + " has the wrong size");
    write_array(f, "Name=\"" + a.name + "\" NumberOfComponents=\"" + std::to_string(a.components) + "\"", a.values,
                a.components, format);
  }
  f << "</" << tag << ">\n";
}
}  // namespace

void write_vtu(const std::string& path, const VtuGrid& grid, VtuFormat format) {
  if (grid.points_per_cell < 1 || grid.connectivity.size() % grid.points_per_cell != 0)
    throw std::invalid_argument("write_vtu: the connectivity is not whole cells");
  for (int p : grid.connectivity)
    if (p < 0 || p >= static_cast<int>(grid.points.size()))
      throw std::invalid_argument("write_vtu: a cell names a point that does not exist");
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  const std::size_t n = grid.points.size(), m = grid.num_cells();
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (const auto& p : grid.points) xyz.insert(xyz.end(), {p.x(), p.y(), 0.0});
  std::vector<std::int32_t> connectivity(grid.connectivity.begin(), grid.connectivity.end()), offsets(m);
  for (std::size_t c = 0; c < m; ++c) offsets[c] = static_cast<std::int32_t>((c + 1) * grid.points_per_cell);
  const std::vector<std::uint8_t> types(m, static_cast<std::uint8_t>(grid.cell_type));

  f << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << m << "\">\n<Points>\n";
  write_array(f, "NumberOfComponents=\"3\"", xyz, 3, format);
  f << "</Points>\n<Cells>\n";
  write_array(f, "Name=\"connectivity\"", connectivity, grid.points_per_cell, format);
  write_array(f, "Name=\"offsets\"", offsets, 1, format);
  write_array(f, "Name=\"types\"", types, 1, format);
  f << "</Cells>\n";
  write_data(f, "PointData", grid.point_data, n, format);
  write_data(f, "CellData", grid.cell_data, m, format);
  f << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if (!f) throw std::runtime_error("write_vtu: writing " + path + " failed");
}

double von_mises_plane_strain(const Eigen::Vector3d& s, double nu) {
  const double zz = nu * (s[0] + s[1]);
  return std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - zz) * (s[1] - zz) + (zz - s[0]) * (zz - s[0])) +
                   3 * s[2] * s[2]);
}

namespace {
VtuGrid triangle_grid(const Mesh& mesh, const Eigen::VectorXd& u) {
  if (u.size() != mesh.num_dofs()) throw std::invalid_argument("write_vtu: u does not match the mesh");
  VtuGrid g;
  g.points = mesh.nodes;
  for (const auto& t : mesh.triangles) g.connectivity.insert(g.connectivity.end(), t.begin(), t.end());
  if (mesh.degree() == 2) {
    // VTK_QUADRATIC_TRIANGLE: the three vertices, then the midpoints of edges 0-1, 1-2, 2-0,
    // the order of p2_element_nodes
    g.cell_type = 22;
    g.points_per_cell = 6;
    g.connectivity.clear();
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const std::array<int, 6> nodes = p2_element_nodes(mesh, t);
      g.connectivity.insert(g.connectivity.end(), nodes.begin(), nodes.end());
    }
  }
  VtuArray displacement{"displacement", 3, {}};
  for (int a = 0; a < mesh.num_nodes(); ++a) displacement.values.insert(displacement.values.end(), {u[2 * a], u[2 * a + 1], 0.0});
  g.point_data.push_back(std::move(displacement));
  return g;
}
}  // namespace

VtuGrid body_grid(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u) {
  VtuGrid g = triangle_grid(mesh, u);
  const std::vector<Eigen::Vector3d> stress = element_stresses(mesh, material, u);
  const char* names[] = {"sigma_xx", "sigma_yy", "sigma_xy"};
  for (int k = 0; k < 3; ++k) {
    VtuArray a{names[k], 1, {}};
    for (const auto& s : stress) a.values.push_back(s[k]);
    g.cell_data.push_back(std::move(a));
  }
  VtuArray mises{"von_mises", 1, {}};
  for (const auto& s : stress) mises.values.push_back(von_mises_plane_strain(s, material.nu()));
  g.cell_data.push_back(std::move(mises));
  return g;
}

void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::VectorXd& u,
               const std::vector<Eigen::Vector3d>& stress) {
  if (stress.size() != mesh.triangles.size()) throw std::invalid_argument("write_vtu: field sizes do not match the mesh");
  VtuGrid g = triangle_grid(mesh, u);
  VtuArray s{"stress", 3, {}};
  for (const auto& t : stress) s.values.insert(s.values.end(), {t[0], t[1], t[2]});
  g.cell_data.push_back(std::move(s));
  write_vtu(path, g, VtuFormat::ascii);
}

void write_curve_vtu(const std::string& path, const std::vector<double>& x, const std::vector<CurveField>& fields,
                     VtuFormat format) {
  VtuGrid g;
  g.cell_type = 3;  // VTK_LINE
  g.points_per_cell = 2;
  for (std::size_t i = 0; i < x.size(); ++i) {
    g.points.emplace_back(x[i], 0.0);
    if (i > 0) g.connectivity.insert(g.connectivity.end(), {static_cast<int>(i) - 1, static_cast<int>(i)});
  }
  for (const CurveField& field : fields) {
    if (field.value.size() != x.size()) throw std::invalid_argument("write_curve_vtu: " + field.name + " has the wrong size");
    g.point_data.push_back({field.name, 1, field.value});
  }
  write_vtu(path, g, format);
}

}  // namespace mortar
