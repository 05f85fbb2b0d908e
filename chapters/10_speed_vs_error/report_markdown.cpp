#include "chapters/10_speed_vs_error/report_markdown.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "chapters/10_speed_vs_error/report_csv.hpp"

namespace tri::ch10 {
namespace {

std::string error_cell(const AlgorithmSummary& s) {
  return format_error_rate(s.missed == 0 && s.extra == 0 ? 0.0 : s.error_rate());
}

std::string scene_list(const BenchReport& report) {
  std::set<std::string> seen;
  std::ostringstream text;
  for (const Measurement& m : report.rows) {
    if (!seen.insert(m.scene).second) continue;
    if (seen.size() > 1) text << ", ";
    text << m.scene << " (" << m.triangles << " triangles)";
  }
  return text.str();
}

std::size_t scene_count(const BenchReport& report) {
  std::set<std::pair<std::string, std::string>> scenes;
  for (const Measurement& m : report.rows) scenes.emplace(m.scene, m.grid);
  return scenes.size();
}

// "X Mpix/s (memset A, vector stores B)": the ceiling and the two fills it is the faster of.
std::string ceiling_cell(const FillCeiling& ceiling) {
  return format_mpix(ceiling.mpix_per_s()) + " Mpix/s (memset " +
         format_mpix(ceiling.memset_mpix_per_s) + ", vector stores " +
         format_mpix(ceiling.vector_stores_mpix_per_s) + ")";
}

}  // namespace

std::string to_markdown(const BenchReport& report, std::span<const AlgorithmSummary> summaries) {
  const Machine& machine = report.machine;
  std::ostringstream md;
  md << "# Speed against error: the measured report\n\n"
     << "Written by `10_speed_vs_error` (" << size_name(report.size) << " setting). Every "
     << "registered algorithm drew the same " << scene_count(report) << " scenes on a "
     << report.width << "×" << report.height << " canvas: " << scene_list(report)
     << ", each with integer and with 1/256-grid vertices. Every measurement is in "
        "`10_report.csv`; the plot is `10_speed_vs_error.svg`.\n\n";
  md << "## Machine\n\n"
     << "| | |\n|---|---|\n"
     << "| nproc | " << machine.threads << " |\n"
     << "| CPU | " << machine.cpu_model << " |\n"
     << "| compiler | " << machine.compiler << " |\n"
     << "| build type | " << machine.build_type << " |\n"
     << "| write ceiling, 1 thread, " << report.width << "×" << report.height << " | "
     << ceiling_cell(report.ceilings.one_thread) << " |\n"
     << "| write ceiling, " << report.ceilings.threads << " threads started per fill | "
     << ceiling_cell(report.ceilings.all_threads) << " |\n";
  for (const SizedCeiling& reference : report.reference_ceilings) {
    // The suite's own canvas already has its row: the median over the scenes.
    if (reference.side == report.width && reference.side == report.height) continue;
    md << "| write ceiling, 1 thread, " << reference.side << "×" << reference.side << " | "
       << ceiling_cell(reference.one_thread) << " |\n";
  }
  md << "| External peers | " << machine.external_peers << " |\n\n";
  md << "## How it was measured\n\n"
     << "Each (algorithm, scene): one warm-up draw of the whole scene, repetitions per sample "
        "raised until a sample lasts at least the target, then timed samples with "
        "`std::chrono::steady_clock`; the speed is the median sample, single-threaded unless "
        "the algorithm is a threaded one. Pixels written are counted once, in a separate draw "
        "with write counts on. The write ceiling is the faster of `memset` and 16-byte vector "
        "stores over every pixel of the same canvas, measured before each scene (the table "
        "quotes the median over scenes): no rasterizer that stores 4 bytes per pixel can write "
        "pixels faster. Threaded algorithms are compared with the faster of the one-thread "
        "ceiling and the fills by as many threads as the machine has, started for each fill as "
        "a batch starts them. The error is "
        "`measure_error` against chapter 07's exact oracle "
     << (report.error_triangle_limit == 0
             ? std::string("on the same scenes (every triangle).")
             : "on the first " + std::to_string(report.error_triangle_limit) +
                   " triangles of each scene (the full scenes only with --full).")
     << "\n\n";
  md << "## Algorithms\n\n"
     << "Speeds of a scene kind are the geometric mean of its two grids; *Mpix/s all* is the "
        "geometric mean over every scene (the plot's y), *of ceiling* the same mean of "
        "Mpix/s ÷ the write ceiling. *error rate* is (missed + extra) per covered pixel over "
        "every scene (the plot's x); gaps and overdraw are counted on the mesh scenes (mesh, "
        "fan); *order-dep.* counts pixels that change with the vertex order.\n\n"
     << "| algorithm | chapter | rule | Mpix/s large | tris/s tiny | tris/s mesh | Mpix/s all | "
        "of ceiling | error rate | missed | extra | gaps | overdraw | order-dep. |\n"
     << "|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const AlgorithmSummary& s : summaries) {
    md << "| `" << s.algorithm << "`" << (s.threaded ? " (threaded)" : "") << " | " << s.chapter
       << " | " << s.rule << " | " << format_mpix(s.large_mpix_per_s) << " | "
       << human_rate(s.tiny_tris_per_s) << " | " << human_rate(s.mesh_tris_per_s) << " | "
       << format_mpix(s.mpix_per_s) << " | " << format_number(100 * s.ratio_to_ceiling, 3) << "% | "
       << error_cell(s) << " | " << s.missed << " | " << s.extra << " | " << s.gaps << " | "
       << s.overdraw << " | " << s.order_dependent << " |\n";
  }
  return md.str();
}

}  // namespace tri::ch10
