// LAMMPS custom dump -> VTK: the files written are read back with VTK's own reader.
#include "coupling/lammps_dump.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLStructuredGridReader.h>
#endif

namespace fs = std::filesystem;
using namespace runin::coupling;

namespace {
fs::path write_dump(const fs::path &dir) {
  fs::create_directories(dir);
  const fs::path path = dir / "two.dump";
  std::ofstream out(path);
  for (int step : {0, 100}) {
    out << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 1\n0 1\n0 1\n"
        << "ITEM: ATOMS id type x y z radius f_RUNIN_WEAR_STATE[1]\n"
        << "1 1 0.1 0.2 0.3 1e-6 " << step * 1e-20 << "\n2 2 0.4 0.5 0.6 2e-6 " << step * 2e-20 << "\n";
  }
  return path;
}
}  // namespace

TEST(LammpsDump, ReadsEverySnapshotAndColumn) {
  const auto dir = fs::temp_directory_path() / "runin_dump_test";
  const auto snaps = read_custom_dump(write_dump(dir).string());
  ASSERT_EQ(snaps.size(), 2u);
  EXPECT_EQ(snaps[1].timestep, 100);
  EXPECT_DOUBLE_EQ(snaps[1].values[snaps[1].column("f_RUNIN_WEAR_STATE[1]", "t")][1], 100 * 2e-20);
  EXPECT_THROW(snaps[0].column("vx", "t"), InputFormatError);
  fs::remove_all(dir);
}

TEST(LammpsDump, TruncatedFileNamesTheLine) {
  const auto dir = fs::temp_directory_path() / "runin_dump_bad";
  fs::create_directories(dir);
  { std::ofstream(dir / "bad.dump") << "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n3\n"; }
  try {
    read_custom_dump((dir / "bad.dump").string());
    FAIL() << "expected InputFormatError";
  } catch (const InputFormatError &e) {
    EXPECT_NE(std::string(e.what()).find("bad.dump:4: truncated"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

#ifdef RUNIN_HAVE_VTK
TEST(VtkExport, RoundTripThroughVtkReader) {
  const auto dir = fs::temp_directory_path() / "runin_vtk_test";
  const auto dump = write_dump(dir);
  const auto written = write_vtk_series(read_custom_dump(dump.string()), dump.string(), (dir / "vtk").string(), "asp");
  ASSERT_EQ(written.size(), 3u);
  EXPECT_TRUE(fs::exists(dir / "vtk" / "asp.pvd"));

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((dir / "vtk" / "asp_100.vtp").c_str());
  reader->Update();
  vtkPolyData *poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 2);
  double p[3];
  poly->GetPoint(1, p);
  EXPECT_DOUBLE_EQ(p[2], 0.6);
  vtkDataArray *wear = poly->GetPointData()->GetArray("f_RUNIN_WEAR_STATE[1]");
  ASSERT_NE(wear, nullptr);
  EXPECT_DOUBLE_EQ(wear->GetTuple1(1), 100 * 2e-20);
  EXPECT_EQ(poly->GetNumberOfVerts(), 2);
  for (const auto &entry : fs::directory_iterator(dir / "vtk"))
    EXPECT_EQ(entry.path().extension().string().find(".part"), std::string::npos);
  fs::remove_all(dir);
}

TEST(VtkExport, SurfaceSeriesRoundTrip) {
  const auto dir = fs::temp_directory_path() / "runin_vtk_surface_test";
  SurfaceFrame frame;
  frame.time = 0.5;
  frame.nu = 3;
  frame.nv = 2;
  std::vector<double> pressure;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      frame.points.push_back({0.1 * i, 0.2 * j, 0.0});
      pressure.push_back(10.0 * i + j);
    }
  frame.fields.emplace_back("pressure", pressure);
  const auto written = write_surface_series({frame, frame}, (dir / "vtk").string(), "contact");
  ASSERT_EQ(written.size(), 3u);

  vtkNew<vtkXMLStructuredGridReader> reader;
  reader->SetFileName(written[1].c_str());
  reader->Update();
  vtkStructuredGrid *grid = reader->GetOutput();
  int dims[3];
  grid->GetDimensions(dims);
  EXPECT_EQ(dims[0], 3);
  EXPECT_EQ(dims[1], 2);
  double p[3];
  grid->GetPoint(4, p);
  EXPECT_DOUBLE_EQ(p[0], 0.1);
  EXPECT_DOUBLE_EQ(p[1], 0.2);
  EXPECT_DOUBLE_EQ(grid->GetPointData()->GetArray("pressure")->GetTuple1(5), 21.0);

  frame.fields[0].second.pop_back();
  EXPECT_THROW(write_surface_series({frame}, (dir / "bad").string(), "contact"), std::invalid_argument);
  fs::remove_all(dir);
}
#endif
