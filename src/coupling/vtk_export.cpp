#include "coupling/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLStructuredGridWriter.h>

#include <cmath>
#include <cstdio>
#include <vector>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace runin::coupling {

namespace fs = std::filesystem;

namespace {

// A field with NaN or inf is never written (ParaView would show it as plausible colours): the caller's run
// stops with the file, array and point named.
void check_finite(vtkPointSet *data, const fs::path &destination) {
  std::vector<vtkDataArray *> arrays{data->GetPoints() ? data->GetPoints()->GetData() : nullptr};
  vtkPointData *fields = data->GetPointData();
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a) arrays.push_back(fields->GetArray(a));
  for (vtkDataArray *array : arrays) {
    if (!array) continue;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
        if (!std::isfinite(array->GetComponent(i, c)))
          throw std::runtime_error(destination.filename().string() + ": non-finite value in " +
                                   (array->GetName() ? std::string("'") + array->GetName() + "'" : "the points") +
                                   " at point " + std::to_string(i) + ": the solution diverged; no file written");
  }
}

template <class Writer, class Data>
void write_atomically(Data &data, const fs::path &destination) {
  check_finite(data, destination);
  const fs::path temp = destination.string() + ".part";
  vtkNew<Writer> writer;
  writer->SetFileName(temp.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();  // ParaView reads it; zlib took a fifth of a piston-ring run
  if (writer->Write() != 1) {
    fs::remove(temp);
    throw std::runtime_error("cannot write VTK file " + destination.string());
  }
  fs::rename(temp, destination);
}

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

  write_atomically<vtkXMLPolyDataWriter>(poly, destination);
}

void write_collection(const std::vector<std::pair<std::string, std::string>> &time_and_file, const fs::path &pvd) {
  std::string collection = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto &[time, file] : time_and_file)
    collection += "    <DataSet timestep=\"" + time + "\" file=\"" + file + "\"/>\n";
  collection += "  </Collection>\n</VTKFile>\n";
  const fs::path temp = pvd.string() + ".part";
  {
    std::ofstream out(temp);
    out << collection;
    if (!out) throw std::runtime_error("cannot write " + pvd.string());
  }
  fs::rename(temp, pvd);
}

}  // namespace

std::vector<std::string> write_vtk_series(const std::vector<DumpSnapshot> &snapshots, const std::string &dump_path,
                                          const std::string &output_dir, const std::string &stem) {
  fs::create_directories(output_dir);
  std::vector<std::string> written;
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto &snap : snapshots) {
    const std::string name = stem + "_" + std::to_string(snap.timestep) + ".vtp";
    write_snapshot(snap, dump_path, fs::path(output_dir) / name);
    written.push_back((fs::path(output_dir) / name).string());
    entries.emplace_back(std::to_string(snap.timestep), name);
  }
  const fs::path pvd = fs::path(output_dir) / (stem + ".pvd");
  write_collection(entries, pvd);
  written.push_back(pvd.string());
  return written;
}

void SurfaceFrame::validate() const {
  const std::size_t n = static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv);
  if (nu < 1 || nv < 1) throw std::invalid_argument("surface frame: grid size must be at least 1 x 1");
  if (points.size() != n) throw std::invalid_argument("surface frame: expected nu*nv points");
  for (const auto &[name, values] : fields)
    if (values.size() != n) throw std::invalid_argument("surface frame: field " + name + " needs nu*nv values");
}

std::vector<std::string> write_surface_series(const std::vector<SurfaceFrame> &frames, const std::string &output_dir,
                                              const std::string &stem) {
  fs::create_directories(output_dir);
  std::vector<std::string> written;
  std::vector<std::pair<std::string, std::string>> entries;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const SurfaceFrame &frame = frames[f];
    frame.validate();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(frame.points.size()));
    for (std::size_t a = 0; a < frame.points.size(); ++a)
      points->SetPoint(static_cast<vtkIdType>(a), frame.points[a].data());
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(frame.nu, frame.nv, 1);
    grid->SetPoints(points);
    for (const auto &[name, values] : frame.fields) {
      vtkNew<vtkDoubleArray> array;
      array->SetName(name.c_str());
      array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
      for (std::size_t a = 0; a < values.size(); ++a) array->SetValue(static_cast<vtkIdType>(a), values[a]);
      grid->GetPointData()->AddArray(array);
    }
    char index[24];  // any size_t: up to 20 digits
    std::snprintf(index, sizeof index, "%04zu", f);
    const std::string name = stem + "_" + index + ".vts";
    write_atomically<vtkXMLStructuredGridWriter>(grid, fs::path(output_dir) / name);
    written.push_back((fs::path(output_dir) / name).string());
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", frame.time);
    entries.emplace_back(time, name);
  }
  const fs::path pvd = fs::path(output_dir) / (stem + ".pvd");
  write_collection(entries, pvd);
  written.push_back(pvd.string());
  return written;
}

}  // namespace runin::coupling
