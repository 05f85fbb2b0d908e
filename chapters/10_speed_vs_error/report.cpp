#include "chapters/10_speed_vs_error/report.hpp"

#include "chapters/10_speed_vs_error/coverage_report.hpp"
#include "chapters/10_speed_vs_error/plot_svg.hpp"
#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "chapters/10_speed_vs_error/report_markdown.hpp"
#include "chapters/10_speed_vs_error/scaling_report.hpp"
#include "chapters/10_speed_vs_error/summary.hpp"
#include "common/output_files.hpp"

namespace tri::ch10 {

ReportFiles render_report(const BenchReport& report, const CoverageReport& coverage,
                          std::span<const ScalingPoint> scaling, std::span<const ShapeRate> shapes,
                          const std::optional<UserPathComparison>& user_path) {
  const std::vector<AlgorithmSummary> summaries = summarize(report.rows);
  const std::vector<CoverageSummary> coverage_summaries =
      summarize_coverage(coverage.rows, report.rows);
  const std::string machine_line = report.machine.cpu_model + " (" +
                                   std::to_string(report.machine.threads) + " threads), " +
                                   report.machine.compiler + ", " + report.machine.build_type;
  const std::string subtitle = std::string(size_name(report.size)) + " setting, " +
                               std::to_string(report.width) + "×" + std::to_string(report.height) +
                               " canvas, " + machine_line;
  return {to_csv(report.rows),
          to_markdown(report, summaries) + user_path_markdown(user_path) +
              coverage_markdown(coverage_summaries, coverage.rows, coverage.peer_status) +
              scaling_markdown(scaling) + blend2d_shapes_markdown(shapes, report.machine),
          to_svg(report, summaries),
          coverage_csv(coverage.rows),
          coverage_svg(coverage_summaries, subtitle),
          scaling_csv(scaling),
          scaling_svg(scaling, "triangles", machine_line),
          scaling_svg(scaling, "canvas", machine_line),
          blend2d_shapes_csv(shapes),
          bl_bench_json(shapes, report.machine),
          user_path_csv(user_path)};
}

std::vector<std::filesystem::path> report_paths(const std::filesystem::path& folder) {
  return {folder / csv_file_name,
          folder / markdown_file_name,
          folder / svg_file_name,
          folder / coverage_csv_file_name,
          folder / coverage_svg_file_name,
          folder / scaling_csv_file_name,
          folder / scaling_triangles_svg_file_name,
          folder / scaling_canvas_svg_file_name,
          folder / blend2d_shapes_csv_file_name,
          folder / blend2d_shapes_json_file_name,
          folder / user_path_csv_file_name};
}

void save_report(const std::filesystem::path& folder, const BenchReport& report,
                 const CoverageReport& coverage, std::span<const ScalingPoint> scaling,
                 std::span<const ShapeRate> shapes,
                 const std::optional<UserPathComparison>& user_path, std::ostream& log) {
  const ReportFiles files = render_report(report, coverage, scaling, shapes, user_path);
  const auto paths = report_paths(folder);
  const std::string* contents[] = {&files.csv,
                                   &files.markdown,
                                   &files.svg,
                                   &files.coverage_csv,
                                   &files.coverage_svg,
                                   &files.scaling_csv,
                                   &files.scaling_triangles_svg,
                                   &files.scaling_canvas_svg,
                                   &files.blend2d_shapes_csv,
                                   &files.blend2d_shapes_json,
                                   &files.user_path_csv};
  OutputTransaction set;
  for (std::size_t i = 0; i < paths.size(); ++i) set.stage(paths[i], bytes_of_text(*contents[i]));
  set.commit();
  for (const auto& path : paths) log << "wrote " << path.string() << "\n";
}

}  // namespace tri::ch10
