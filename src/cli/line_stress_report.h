// Subsurface stress of the line contacts (journal bearing halves, piston ring faces) in the CLI: the start and
// end frames, their VTK series and the summary lines with the yield verdict (doc/subsurface_stress.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "continuum/contact_stress.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {

struct LineStressFrame {
  double time = 0.0;
  continuum::LineContactStress stress;
};

// One contact's start and end frames and how to name its bodies in the summary.
struct LineStressReport {
  std::string contact;                 // "lower half", "ring A", ...
  std::string label_a, label_b;        // "bearing (Steel1020)", "shaft"
  std::string field_a, field_b;        // VTK array stems: "bearing", "shaft"
  std::string materials_hint;          // key to set when S_y is unknown, e.g. "contact.materials"
  bool tabor_a = false, tabor_b = false;  // the body's S_y is Tabor's H / 2.8 (the file gives no S_y)
  std::vector<LineStressFrame> frames;
  std::string cross_check;             // optional extra line (closed form vs influence tier at the start)
};

// The material for the verdict: nu as given, yield strength S_y, else Tabor's H / 2.8, else 0 (unknown).
tribo::Material verdict_material(const tribo::Material &m);
// "bearing (Steel1020)" or "bearing".
std::string body_label(const std::string &body, const std::string &material_name);

#ifdef RUNIN_HAVE_VTK
// A stress section as a VTK frame without arrays: points (x, 0, -depth) [m] of the field's grid.
coupling::SurfaceFrame section_frame(double time, const tribo::StressField &grid);
#endif

// Section below the contact: points (x, 0, -depth) [m], arrays von_mises_<a>_Pa, tresca_<a>_Pa,
// von_mises_<b>_Pa, tresca_<b>_Pa. Returns the written files (.pvd last).
std::vector<std::string> write_line_stress(const LineStressReport &report, const std::filesystem::path &dir,
                                           const std::string &stem);

// Summary lines of one contact; WARNING lines for yielding bodies are appended to `warnings`.
void print_line_stress(const LineStressReport &report, std::vector<std::string> &warnings);

}  // namespace runin::cli
