#include "coupling/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace runin::coupling {

namespace fs = std::filesystem;

namespace {

void write_snapshot(const DumpSnapshot &snap, const std::string &dump_path, const fs::path &destination) {
  const std::size_t ix = snap.column("x", dump_path), iy = snap.column("y", dump_path), iz = snap.column("z", dump_path);
  const std::size_t n = snap.values[ix].size();

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(n));
  vtkNew<vtkCellArray> vertices;
  for (std::size_t a = 0; a < n; ++a) {
    points->SetPoint(static_cast<vtkIdType>(a), snap.values[ix][a], snap.values[iy][a], snap.values[iz][a]);
    const vtkIdType id = static_cast<vtkIdType>(a);
    vertices->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(vertices);
  for (std::size_t c = 0; c < snap.columns.size(); ++c) {
    if (c == ix || c == iy || c == iz) continue;
    vtkNew<vtkDoubleArray> array;
    array->SetName(snap.columns[c].c_str());
    array->SetNumberOfValues(static_cast<vtkIdType>(n));
    for (std::size_t a = 0; a < n; ++a) array->SetValue(static_cast<vtkIdType>(a), snap.values[c][a]);
    poly->GetPointData()->AddArray(array);
  }

  const fs::path temp = destination.string() + ".part";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(temp.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToBinary();
  if (writer->Write() != 1) {
    fs::remove(temp);
    throw std::runtime_error("cannot write VTK file " + destination.string());
  }
  fs::rename(temp, destination);
}

}  // namespace

std::vector<std::string> write_vtk_series(const std::vector<DumpSnapshot> &snapshots, const std::string &dump_path,
                                          const std::string &output_dir, const std::string &stem) {
  fs::create_directories(output_dir);
  std::vector<std::string> written;
  std::string collection = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto &snap : snapshots) {
    const std::string name = stem + "_" + std::to_string(snap.timestep) + ".vtp";
    write_snapshot(snap, dump_path, fs::path(output_dir) / name);
    written.push_back((fs::path(output_dir) / name).string());
    collection += "    <DataSet timestep=\"" + std::to_string(snap.timestep) + "\" file=\"" + name + "\"/>\n";
  }
  collection += "  </Collection>\n</VTKFile>\n";

  const fs::path pvd = fs::path(output_dir) / (stem + ".pvd");
  const fs::path temp = pvd.string() + ".part";
  {
    std::ofstream out(temp);
    out << collection;
    if (!out) throw std::runtime_error("cannot write " + pvd.string());
  }
  fs::rename(temp, pvd);
  written.push_back(pvd.string());
  return written;
}

}  // namespace runin::coupling
