#include "common/study/vtu.hpp"

#include <fstream>
#include <stdexcept>

namespace mortar {

void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::VectorXd& u,
               const std::vector<Eigen::Vector3d>& stress) {
  if (u.size() != mesh.num_dofs() || stress.size() != mesh.triangles.size())
    throw std::invalid_argument("write_vtu: field sizes do not match the mesh");
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  const std::size_t n = mesh.nodes.size(), m = mesh.triangles.size();
  f << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << m << "\">\n"
    << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : mesh.nodes) f << p.x() << " " << p.y() << " 0\n";
  f << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : mesh.triangles) f << t[0] << " " << t[1] << " " << t[2] << "\n";
  f << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 1; c <= m; ++c) f << 3 * c << "\n";
  f << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < m; ++c) f << "5\n";  // VTK_TRIANGLE
  f << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n"
    << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t a = 0; a < n; ++a) f << u[2 * a] << " " << u[2 * a + 1] << " 0\n";
  f << "</DataArray>\n</PointData>\n<CellData>\n"
    << "<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" "
       "ComponentName0=\"sigma_xx\" ComponentName1=\"sigma_yy\" ComponentName2=\"sigma_xy\" "
       "format=\"ascii\">\n";
  for (const auto& s : stress) f << s[0] << " " << s[1] << " " << s[2] << "\n";
  f << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if (!f) throw std::runtime_error("write_vtu: writing " + path + " failed");
}

void write_curve_vtu(const std::string& path, const std::vector<double>& x, const std::vector<CurveField>& fields) {
  for (const CurveField& field : fields)
    if (field.value.size() != x.size()) throw std::invalid_argument("write_curve_vtu: " + field.name + " has the wrong size");
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  const std::size_t n = x.size(), m = n > 0 ? n - 1 : 0;
  f << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << m << "\">\n"
    << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (double xi : x) f << xi << " 0 0\n";
  f << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < m; ++c) f << c << " " << c + 1 << "\n";
  f << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 1; c <= m; ++c) f << 2 * c << "\n";
  f << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < m; ++c) f << "3\n";  // VTK_LINE
  f << "</DataArray>\n</Cells>\n<PointData>\n";
  for (const CurveField& field : fields) {
    f << "<DataArray type=\"Float64\" Name=\"" << field.name << "\" format=\"ascii\">\n";
    for (double v : field.value) f << v << "\n";
    f << "</DataArray>\n";
  }
  f << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if (!f) throw std::runtime_error("write_curve_vtu: writing " + path + " failed");
}

}  // namespace mortar
