// Chapter 10's report: every registered algorithm on the same scene suites, timed and compared
// with the exact oracle; writes 10_report.csv, 10_report.md and 10_speed_vs_error.svg.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/report.hpp"
#include "chapters/10_speed_vs_error/scaling.hpp"
#include "chapters/10_speed_vs_error/snapshot.hpp"
#include "chapters/10_speed_vs_error/suites.hpp"
#include "chapters/10_speed_vs_error/user_path.hpp"
#include "common/cli.hpp"
#include "common/output_files.hpp"
#include "common/printable_text.hpp"
#include "measure/peers/external_peers.hpp"
#include "measure/registry.hpp"

namespace {

// What a run measures: registered algorithms and the external peers this build has, for both
// parts of the report (inside-or-outside, then coverage).
struct Selection {
  std::vector<tri::TriangleAlgorithm> algorithms;
  std::vector<tri::ExternalPeer> peers;
  std::vector<tri::ch09::AreaAlgorithm> area_algorithms;
  std::vector<tri::CoveragePeer> coverage_peers;
};

// The algorithms and peers named in a comma-separated list (all of them without --only).
Selection selected(const std::optional<std::string>& names) {
  Selection all{tri::registered_algorithms(), tri::external_peers(),
                tri::registered_area_algorithms(), tri::coverage_peers()};
  if (!names) return all;
  std::vector<std::string> valid;
  for (const auto& a : all.algorithms) valid.emplace_back(a.name);
  for (const auto& p : all.peers) valid.emplace_back(p.name);
  for (const auto& a : all.area_algorithms) valid.emplace_back(a.name);
  for (const auto& p : all.coverage_peers) valid.emplace_back(p.name);
  std::vector<std::string> chosen_names;
  try {
    chosen_names = tri::parse_name_list("only", *names, valid);
  } catch (const tri::UsageError& e) {
    if (!all.peers.empty()) throw;
    throw tri::UsageError(std::string(e.what()) +
                          "; external peers: " + tri::external_peer_status({}));
  }
  Selection chosen;
  for (const std::string& name : chosen_names) {
    if (const tri::TriangleAlgorithm* algorithm = tri::find_named(all.algorithms, name)) {
      chosen.algorithms.push_back(*algorithm);
    } else if (const auto* area = tri::find_named(all.area_algorithms, name)) {
      chosen.area_algorithms.push_back(*area);
    } else if (const tri::ExternalPeer* peer = tri::find_named(all.peers, name)) {
      chosen.peers.push_back(*peer);
    } else {
      chosen.coverage_peers.push_back(*tri::find_named(all.coverage_peers, name));
    }
  }
  return chosen;
}

// The suite's scenes of one kind (--scene) and one grid (--grid); an unknown value is a usage
// error that lists the valid ones.
std::vector<tri::SuiteScene> filtered(std::vector<tri::SuiteScene> scenes,
                                      const std::optional<std::string>& kind,
                                      const std::optional<std::string>& grid) {
  const auto keep_only = [&](const char* option, const std::string& wanted, auto field) {
    std::string valid;
    for (const auto& scene : scenes) {
      const std::string& value = scene.*field;
      if (valid.find(value) == std::string::npos) valid += (valid.empty() ? "" : ", ") + value;
    }
    std::erase_if(scenes, [&](const tri::SuiteScene& s) { return s.*field != wanted; });
    if (scenes.empty()) {
      throw tri::UsageError(std::string("--") + option + " '" + tri::printable_excerpt(wanted) +
                            "' matches no scene (valid: " + valid + ")");
    }
  };
  if (kind) keep_only("scene", *kind, &tri::SuiteScene::name);
  if (grid) keep_only("grid", *grid, &tri::SuiteScene::grid);
  return scenes;
}

}  // namespace

int main(int argc, char** argv) {
  const tri::CommandLine command_line(
      "10_speed_vs_error",
      "Chapter 10, speed against error: draws the same scene suites with every registered\n"
      "algorithm, times them (warm-up, median of repeated samples, beside the write ceiling)\n"
      "and measures their error against the exact oracle; then chapter 09's coverage algorithms\n"
      "against the exact area; then how the time of a frame grows with the triangles and the\n"
      "canvas; then Blend2D's benchmark triangles (N x N boxes, N = 8 to 256, 512x600); and\n"
      "times one algorithm with the raster program as a user would. Writes 10_report.csv,\n"
      "10_coverage.csv, 10_scaling.csv, 10_blend2d_shapes.csv and 10_user_path.csv (every\n"
      "measurement), 10_report.md (the machine, one row per algorithm, the sweeps' and shapes'\n"
      "tables, raster's time beside the report's), 10_blend2d_shapes.json (bl_bench's layout),\n"
      "and the plots\n"
      "10_speed_vs_error.svg, 10_coverage_speed_vs_error.svg, 10_scaling_triangles.svg and\n"
      "10_scaling_canvas.svg. Quick by default (about a minute on two cores); --full for the\n"
      "complete sweep.",
      {{"out", "DIR", "folder for the report (default: out)"},
       {"full", "", "complete sweep: 512x512 canvas, 100,000-triangle mesh, longer samples"},
       {"only", "NAMES",
        "measure only these (comma-separated registry names, or an external peer's name)"},
       {"scene", "KIND",
        "only the scenes of this kind (tiny, medium, large, slivers, mesh, fan, mixed)"},
       {"grid", "GRID", "only the scenes on this vertex grid (integer or 1/256)"},
       {"snapshot", "FILE",
        "also write the measurement snapshot the book's measured numbers come from "
        "(docs/measurements/)"},
       {"commit", "TEXT", "the commit measured, for the snapshot's header (default: unknown)"},
       {"note", "TEXT", "a note for the snapshot's header, e.g. that the machine was shared"},
       {"raster", "FILE",
        "the raster program timed beside the report (default: the one this build made)"}});
  return tri::run_command_line(
      command_line, argc, argv, std::cout, std::cerr, [](const tri::CliArguments& args) {
        const auto size =
            args.has("full") ? tri::ch10::SuiteSize::full : tri::ch10::SuiteSize::quick;
        const Selection selection = selected(args.value("only"));
        // The report's folder and files are checked before minutes of measuring, not after.
        const std::filesystem::path folder = args.value_or("out", "out");
        tri::check_output_folder(folder);
        auto outputs = tri::ch10::report_paths(folder);
        const auto snapshot = args.value("snapshot");
        if (snapshot) outputs.emplace_back(*snapshot);
        tri::check_outputs(outputs);
        tri::ch10::BenchSettings settings = tri::ch10::bench_settings(size);
        settings.scenes =
            filtered(std::move(settings.scenes), args.value("scene"), args.value("grid"));
        std::cout << "10_speed_vs_error: " << selection.algorithms.size() << " algorithms and "
                  << selection.peers.size() << " external peers, then "
                  << selection.area_algorithms.size() << " coverage algorithms and "
                  << selection.coverage_peers.size() << " anti-aliasing peers, x "
                  << settings.scenes.size() << " scenes, " << tri::ch10::size_name(size)
                  << " setting\n";
        const tri::ch10::BenchReport report = tri::ch10::run_benchmark(
            selection.algorithms, selection.peers, settings,
            tri::describe_machine(tri::external_peer_status(selection.peers)), std::cout);
        // One algorithm timed again through `raster --bench`, the way a user times it.
        std::optional<tri::ch10::UserPathComparison> user_path;
        if (const auto* algorithm = tri::ch10::user_path_algorithm(selection.algorithms)) {
          user_path = tri::ch10::measure_user_path(report, *algorithm, settings.scenes,
                                                   args.value_or("raster", TUTORIAL_RASTER_PROGRAM),
                                                   settings.user_path_budget_seconds, std::cout);
        }
        const tri::ch10::CoverageReport coverage{
            tri::ch10::run_coverage_benchmark(selection.area_algorithms, selection.coverage_peers,
                                              settings, std::cout),
            tri::coverage_peer_status(selection.coverage_peers)};
        // How cost grows: the sweeps follow chapter 08's fastest and the peers when selected,
        // and skip when --scene or --grid narrowed the run to some scenes.
        std::vector<tri::ch10::ScalingPoint> scaling;
        if (!args.has("scene") && !args.has("grid")) {
          const auto drawers = tri::ch10::scaling_drawers(selection.algorithms, selection.peers);
          scaling = tri::ch10::run_scaling(drawers, tri::ch10::scaling_settings(size), std::cout);
        }
        // Blend2D's benchmark shapes: every chosen drawer, skipped like the sweeps when --scene
        // or --grid narrowed the run.
        std::vector<tri::ch10::ShapeRate> shapes;
        if (!args.has("scene") && !args.has("grid")) {
          shapes = tri::ch10::run_blend2d_shapes(
              selection.algorithms, selection.peers, selection.area_algorithms,
              selection.coverage_peers, tri::ch10::blend2d_shapes_settings(size), std::cout);
        }
        tri::ch10::save_report(folder, report, coverage, scaling, shapes, user_path, std::cout);
        if (snapshot) {
          const tri::ch10::SnapshotHeader header{args.value_or("commit", "unknown"),
                                                 tri::ch10::utc_date(), tri::peer_versions(),
                                                 args.value_or("note", "")};
          tri::write_file_safely(*snapshot, tri::bytes_of_text(tri::ch10::snapshot_text(
                                                report, coverage, header, shapes)));
          std::cout << "wrote " << *snapshot << '\n';
        }
        return 0;
      });
}
