#include "tools/raster_app.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <numeric>
#include <optional>
#include <string>

#include <unistd.h>

#include <iostream>

#include "common/cli.hpp"
#include "common/image_io.hpp"
#include "common/output_files.hpp"
#include "common/printable_text.hpp"
#include "common/progress.hpp"
#include "measure/area_error.hpp"
#include "measure/registry.hpp"
#include "measure/render_scene.hpp"
#include "measure/timing.hpp"
#include "tools/out_of_memory.hpp"
#include "tools/pixel_formats.hpp"

namespace tri {
namespace {

// "a and b", "a, b and c": the drawables that write every one of `outputs`, named from their
// descriptors so no text names an algorithm that cannot; empty when none does.
std::string names_writing(std::span<const Drawable> drawables,
                          std::initializer_list<Output> outputs) {
  std::vector<const Drawable*> writers = drawables_writing(drawables, *outputs.begin());
  std::erase_if(writers, [&](const Drawable* d) {
    return !std::ranges::all_of(outputs, [&](Output o) { return d->writes(o); });
  });
  std::string names;
  for (std::size_t i = 0; i < writers.size(); ++i) {
    if (i > 0) names += i + 1 == writers.size() ? " and " : ", ";
    names += writers[i]->name;
  }
  return names;
}

CommandLine raster_command_line(std::span<const Drawable> drawables) {
  const std::string narrow = names_writing(drawables, {Output::index8, Output::mask1});
  return CommandLine(
      "raster",
      "Renders a scene file with one of the book's triangle algorithms.\n"
      "  raster --list\n"
      "  raster --algo NAME --scene FILE [--out FILE.png] [--counts FILE.pgm]\n"
      "  raster --algo NAME --scene FILE --coverage FILE.pgm   (an algorithm of rule area)\n"
      "  raster --algo NAME --scene FILE --bench N\n"
      "  (either of the last two with --format rgba8|index8|mask1|auto)\n"
      "Scene format: 'canvas W H [r g b]', 'tri x0 y0 x1 y1 x2 y2 [r g b]',\n"
      "'line x0 y0 x1 y1 [r g b]', '#' comments; y is up, integers are pixel centres.\n"
      "Limits: lines of at most 65536 bytes, at most 2000000 triangles and lines.\n"
      "Outputs replace their files only when all were written; an output that is the scene,\n"
      "two outputs naming one file, devices, FIFOs, read-only and hard-linked files are\n"
      "refused; a symlinked output is written through to its file. '-' is standard output;\n"
      "/dev/stdout, /dev/stderr and /dev/fd/N are written to, never replaced as files.\n"
      "Work that runs for more than 2 s (--progress-after) prints its progress on standard error.",
      {
          {"list", "", "print every algorithm: NAME, CHAPTER, RULE, summary (tab-separated)"},
          {"algo", "NAME", "the triangle algorithm to draw with (see --list)"},
          {"scene", "FILE", "the scene file to draw"},
          {"out", "FILE.png", "write the picture as PNG ('-': standard output)"},
          {"counts", "FILE.pgm",
           "write per-pixel write counts as binary PGM, saturating at 255 ('-': standard output)"},
          {"coverage", "FILE.pgm",
           "rule area: write the triangles' coverage, summed and clamped to [0, 1], as a 16-bit "
           "binary PGM, value round(65535 x coverage) ('-': standard output)"},
          {"bench", "N",
           "prepare the scene once, then time N draws of it after a warm-up; print the "
           "preparation's time and the median frame's speed"},
          {"force", "", "run a --bench estimated to take more than 10 minutes anyway"},
          {"progress-after", "S",
           "report progress on standard error after S seconds of work and then every S seconds "
           "(default 2; 0 reports every step)"},
          {"format", "F",
           "draw into rgba8 (default), index8 (a byte per pixel: a palette of at most 255 "
           "colours), mask1 (a bit per pixel: one colour) or auto (the narrowest that holds the "
           "scene); index8 and mask1 are drawn by " +
               (narrow.empty() ? "no registered algorithm" : narrow) + " and expanded for the PNG"},
      });
}

void print_list(std::span<const Drawable> drawables, std::ostream& out) {
  for (const Drawable& a : drawables) {
    out << a.name << '\t' << a.chapter << '\t' << rule_name(a.rule) << '\t' << a.summary << '\n';
  }
}

// Roughly how long stb takes per pixel to encode a PNG (16384x16384 took 40-53 s).
constexpr double png_seconds_per_pixel = 170e-9;

// How long work runs before its progress is reported, and between reports (--progress-after).
std::chrono::seconds progress_after(const CliArguments& args) {
  return std::chrono::seconds(args.integer("progress-after", 0, 86'400).value_or(2));
}

Progress progress_of(const CliArguments& args, std::string label, std::uint64_t total,
                     std::ostream& err) {
  const auto after = progress_after(args);
  return Progress(std::move(label), total, err, after, after);
}

// The PNG encoder has no callback: a long encoding is announced with its estimate instead.
std::vector<std::uint8_t> encode_png_saying_so(const CliArguments& args, const Canvas& canvas,
                                               std::ostream& err) {
  const double pixels = static_cast<double>(canvas.width()) * canvas.height();
  const double seconds = pixels * png_seconds_per_pixel;
  if (seconds > std::chrono::duration<double>(progress_after(args)).count()) {
    err << "raster: encoding a " << canvas.width() << "x" << canvas.height() << " PNG, about "
        << human_duration(seconds) << "\n";
  }
  return allocating("the PNG of the " + std::to_string(canvas.width()) + "x" +
                        std::to_string(canvas.height()) + " canvas",
                    pixels * 4, "the scene's canvas size", [&] { return encode_png(canvas); });
}

// "the 16384x16384 canvas", for messages about memory.
std::string canvas_words(const Scene& scene) {
  return "the " + std::to_string(scene.width) + "x" + std::to_string(scene.height) + " canvas";
}

double pixel_count(const Scene& scene) {
  return static_cast<double>(scene.width) * static_cast<double>(scene.height);
}

// The scene, read with progress by bytes read when its size is known.
Scene load_scene_saying_so(const CliArguments& args, const std::string& path, std::ostream& err) {
  std::error_code unknown;
  const std::uintmax_t size = std::filesystem::file_size(path, unknown);
  Progress reading = progress_of(args, "raster: reading the scene", unknown ? 0 : size, err);
  return load_scene(path,
                    [&](std::uint64_t bytes) { reading.advance(static_cast<double>(bytes)); });
}

// How many pixels one frame of the scene writes, from one draw with write counts.
std::uint64_t pixels_per_frame(const Scene& scene, const TriangleAlgorithm* algorithm) {
  Canvas counted = make_canvas(scene);
  counted.enable_write_counts();
  render_scene(scene, algorithm, counted);
  const auto counts = counted.write_counts();
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

// What a --bench does once before its frames (the scene's triangles copied into what the frames
// draw; for RGBA8 also checked and culled to the canvas), and how long that took: it is printed on
// its own line.
struct Preparation {
  double seconds = 0;
};

Preparation prepare(const std::function<void()>& preparation) {
  return {seconds_of(preparation)};
}

// Times `frames` frames of draw() with the book's one method (measure/timing.hpp): each frame is
// a sample of one draw after an untimed warm-up, and the rates come from the median frame. Prints
// the two lines of docs/DESIGN.md section 9 (`pixels` is what one frame writes); refuses (unless
// forced) a run whose estimate is absurd.
void benchmark(const Preparation& preparation, const std::function<void()>& draw,
               std::size_t triangles, const std::function<std::uint64_t()>& pixels,
               long long frames, bool forced, std::ostream& out, std::ostream& err) {
  const double frame_seconds = seconds_of(draw);  // untimed by the plan: it estimates
  refuse_absurd_run(frame_seconds * static_cast<double>(frames),
                    "--bench " + std::to_string(frames), forced);
  TimingPlan plan;
  plan.samples = static_cast<int>(frames);
  plan.repetitions = 1;
  Progress progress("raster: --bench", static_cast<std::uint64_t>(frames), err);
  const Timing timing = time_interleaved(std::span(&draw, 1), plan, [&](int done) {
                          progress.advance(static_cast<std::uint64_t>(done));
                        }).front();
  const double median = timing.seconds.median;
  out << "preparation_seconds=" << preparation.seconds << '\n';
  out << "triangles=" << triangles << " frames=" << frames << " seconds=" << median
      << " min_seconds=" << timing.seconds.min << " max_seconds=" << timing.seconds.max
      << " tris_per_s=" << (median > 0 ? static_cast<double>(triangles) / median : 0.0)
      << " mpix_per_s=" << mpix_per_second(static_cast<double>(pixels()), median) << '\n';
}

void benchmark(const Scene& scene, const TriangleAlgorithm* algorithm, long long frames,
               bool forced, std::ostream& out, std::ostream& err) {
  Canvas canvas = make_canvas(scene);
  // One drawer for every frame, made before the clock runs: a renderer's threads start once.
  std::optional<BatchDrawer> drawer;
  if (algorithm != nullptr) drawer.emplace(*algorithm);
  BatchDrawer* kept = drawer ? &*drawer : nullptr;
  // The triangles are copied out of the scene, checked and culled once; every frame draws that
  // copy. Counting them is not part of the preparation, so it is done before its clock runs.
  const std::size_t triangles = count_triangles(scene);
  PreparedDrawing prepared;
  const Preparation preparation = prepare([&] {
    prepared = allocating("the prepared triangles of the scene",
                          static_cast<double>(triangles) * sizeof(SceneTriangle),
                          "the scene's triangle count", [&] { return prepare_drawing(scene); });
  });
  benchmark(
      preparation, [&] { draw_prepared(prepared, kept, canvas); }, triangles,
      [&] { return pixels_per_frame(scene, algorithm); }, frames, forced, out, err);
}

// An algorithm of rule area: its coverage of the scene's triangles (lines have no area and are
// left out), benchmarked or written as a 16-bit PGM (docs/DESIGN.md section 9).
int run_coverage(const CliArguments& args, const Scene& scene, const ch09::AreaAlgorithm& area,
                 std::optional<long long> frames, std::ostream& out, std::ostream& err) {
  ch09::CoverageCanvas canvas = allocating(
      "the coverage values of " + canvas_words(scene), pixel_count(scene) * sizeof(float),
      "the scene's canvas size", [&] { return ch09::CoverageCanvas(scene.width, scene.height); });
  if (frames) {
    std::vector<SceneTriangle> triangles;
    const Preparation preparation = prepare([&] { triangles = scene_triangles(scene); });
    benchmark(
        preparation,
        [&] {
          canvas.clear();
          ch09::draw_coverage(area, canvas, triangles);
        },
        triangles.size(),
        [&] { return touched_pixels(area, scene.width, scene.height, triangles); }, *frames,
        args.has("force"), out, err);
    return 0;
  }
  Progress drawing = progress_of(args, "raster: coverage", scene.primitives.size(), err);
  const std::size_t refused =
      render_coverage(scene, area, canvas, [&](double done) { drawing.advance(done); });
  if (refused > 0) {
    throw std::runtime_error(std::to_string(refused) +
                             " triangle(s) have non-finite or out-of-range vertices");
  }
  OutputTransaction files(&out);
  const std::string path = *args.value("coverage");
  files.stage(path, allocating("the PGM of " + canvas_words(scene), pixel_count(scene) * 2,
                               "the scene's canvas size", [&] { return canvas.pgm_16(); }));
  files.commit();
  std::ostream& report = output_descriptor(path) == STDOUT_FILENO ? err : out;
  const std::size_t triangles = count_triangles(scene);
  report << "drew the coverage of " << triangles << " triangle(s) on " << scene.width << "x"
         << scene.height << " with " << area.name;
  const std::size_t lines = scene.primitives.size() - triangles;
  if (lines > 0) report << " (" << lines << " line(s) left out: a line has no area)";
  report << '\n';
  return 0;
}

// --format, checked before anything is read: the format asked for (nothing for auto, which
// depends on the scene). Refuses what cannot go together.
std::optional<PixelFormat> checked_format(const CliArguments& args,
                                          std::span<const Drawable> drawables,
                                          const Drawable* drawable) {
  const auto name = args.value("format");
  if (!name) return PixelFormat::rgba8;
  const std::optional<PixelFormat> format = parse_format(*name);
  if (!format && *name != "auto") {
    throw UsageError("--format must be rgba8, index8, mask1 or auto, not '" +
                     printable_excerpt(*name) + "'");
  }
  if (drawable != nullptr && !drawable->writes(Output::rgba8)) {
    throw UsageError(std::string(drawable->name) + " has rule " +
                     std::string(rule_name(drawable->rule)) + ": --format is for colour pictures");
  }
  if (drawable == nullptr) throw UsageError("--format goes with --algo NAME");
  if (format && !draws_format(*drawable, *format)) {
    const std::string narrow = names_writing(drawables, {output_of(*format)});
    throw UsageError(std::string(drawable->name) + " draws RGBA8 only; index8 and mask1 are " +
                     "drawn by " + (narrow.empty() ? "no registered algorithm" : narrow) +
                     " (chapter 08, step 8)");
  }
  if (args.has("counts") && format != PixelFormat::rgba8) {
    throw UsageError("--counts counts the writes of the RGBA8 canvas: use --format rgba8");
  }
  return format;
}

// A scene drawn into a narrow format (chapter 08's step 8 canvases): benchmarked, or expanded to
// RGBA8 for the PNG, the same picture an RGBA8 draw gives.
int run_narrow(const CliArguments& args, const Scene& scene, const TriangleAlgorithm& algorithm,
               PixelFormat format, std::optional<long long> frames, bool to_standard_output,
               std::ostream& out, std::ostream& err) {
  if (const auto refusal = format_refusal(scene, format)) throw std::runtime_error(*refusal);
  std::optional<NarrowRender> made;  // its triangles are copied out of the scene once
  const Preparation preparation = prepare([&] {
    allocating("the " + std::string(format_name(format)) + " pixels of " + canvas_words(scene),
               pixel_count(scene) / (format == PixelFormat::mask1 ? 8 : 1),
               "the scene's canvas size", [&] { made.emplace(scene, format, algorithm); });
  });
  NarrowRender& render = *made;
  if (frames) {
    benchmark(
        preparation, [&] { render.draw(); }, count_triangles(scene),
        [&] { return pixels_per_frame(scene, &algorithm); }, *frames, args.has("force"), out, err);
    return 0;
  }
  Progress drawing = progress_of(args, "raster: drawing", count_triangles(scene), err);
  const std::size_t refused = render.draw([&](double done) { drawing.advance(done); });
  if (refused > 0) {
    throw std::runtime_error(std::to_string(refused) +
                             " triangle(s) have non-finite or out-of-range vertices");
  }
  OutputTransaction files(&out);
  if (const auto path = args.value("out")) {
    const Canvas expanded =
        allocating("the RGBA8 picture of " + canvas_words(scene), pixel_count(scene) * 4,
                   "the scene's canvas size", [&] { return render.expanded(); });
    files.stage(*path, encode_png_saying_so(args, expanded, err));
  }
  files.commit();
  std::ostream& report = to_standard_output ? err : out;
  report << "drew " << count_triangles(scene) << " triangle(s) and 0 line(s) on " << scene.width
         << "x" << scene.height << " with " << algorithm.name << " as " << format_name(format)
         << '\n';
  return 0;
}

int run(std::span<const Drawable> drawables, const CliArguments& args, std::ostream& out,
        std::ostream& err) {
  if (args.has("list")) {
    if (args.has("algo") || args.has("scene") || args.has("out") || args.has("counts") ||
        args.has("coverage") || args.has("bench") || args.has("format")) {
      throw UsageError("--list takes no other option");
    }
    print_list(drawables, out);
    return 0;
  }
  const auto scene_path = args.value("scene");
  if (!scene_path) throw UsageError("--scene FILE is required (or --list)");
  progress_after(args);  // a bad value is a usage error before any work
  const Drawable* drawable = nullptr;
  if (const auto name = args.value("algo")) {
    drawable = find_named(drawables, *name);
    if (drawable == nullptr) {
      throw UsageError("unknown algorithm '" + printable_excerpt(*name) +
                       "' (raster --list shows the names)");
    }
  }
  // What it can write decides what it may be asked for; its entry points decide how it draws.
  const bool colours = drawable == nullptr || drawable->writes(Output::rgba8);
  const bool coverage = drawable != nullptr && drawable->writes(Output::coverage16);
  const auto frames = args.integer("bench", 1, 1'000'000);  // every frame's time is kept
  if (frames && (args.has("out") || args.has("counts") || args.has("coverage"))) {
    throw UsageError("--bench writes no image: drop --out, --counts and --coverage");
  }
  if (args.has("force") && !frames) throw UsageError("--force goes with --bench");
  if (!colours && (args.has("out") || args.has("counts"))) {
    throw UsageError(std::string(drawable->name) + " has rule " +
                     std::string(rule_name(drawable->rule)) +
                     ": it computes coverage, not colours; use --coverage FILE.pgm");
  }
  if (!colours && !frames && !args.has("coverage")) {
    throw UsageError(std::string(drawable->name) + " has rule " +
                     std::string(rule_name(drawable->rule)) +
                     ": choose --coverage FILE.pgm or --bench N");
  }
  if (!coverage && args.has("coverage")) {
    throw UsageError("--coverage needs an algorithm of rule area (raster --list shows them)" +
                     (drawable ? ", and " + std::string(drawable->name) + " has rule " +
                                     std::string(rule_name(drawable->rule))
                               : std::string()));
  }

  const std::optional<std::string> format_arg = args.value("format");
  const std::optional<PixelFormat> chosen_format = checked_format(args, drawables, drawable);

  // Every output is checked before any work, so a bad one costs nothing and destroys nothing.
  std::vector<std::filesystem::path> outputs;
  for (const char* option : {"out", "counts", "coverage"}) {
    if (const auto path = args.value(option)) outputs.emplace_back(*path);
  }
  const std::vector<std::filesystem::path> inputs{*scene_path};
  check_outputs(outputs, inputs);
  // '-', /dev/stdout, /dev/stderr and /dev/fd/N are descriptors: written to, never replaced.
  bool to_standard_output = false;
  for (const auto& output : outputs) {
    const std::optional<int> descriptor = output_descriptor(output);
    if (!descriptor) continue;
    to_standard_output = to_standard_output || *descriptor == STDOUT_FILENO;
    if ((*descriptor != STDOUT_FILENO || &out == &std::cout) && ::isatty(*descriptor) == 1) {
      throw UsageError("'" + output.string() +
                       "' would write a binary image to the terminal; redirect it");
    }
  }

  const Scene scene = load_scene_saying_so(args, *scene_path, err);
  if (drawable != nullptr && drawable->coverage != nullptr) {
    return run_coverage(args, scene, *drawable->coverage, frames, out, err);
  }
  const TriangleAlgorithm* algorithm = drawable != nullptr ? drawable->colours : nullptr;
  if (algorithm == nullptr && count_triangles(scene) > 0) {
    throw UsageError(*scene_path + " has triangles: choose an algorithm with --algo NAME");
  }
  if (format_arg) {
    const PixelFormat format = chosen_format ? *chosen_format : narrowest_format(scene, *drawable);
    if (format != PixelFormat::rgba8) {
      return run_narrow(args, scene, *algorithm, format, frames, to_standard_output, out, err);
    }
  }
  if (frames) {
    benchmark(scene, algorithm, *frames, args.has("force"), out, err);
    return 0;
  }

  Canvas canvas = allocating(canvas_words(scene), pixel_count(scene) * 4, "the scene's canvas size",
                             [&] { return make_canvas(scene); });
  if (args.has("counts")) {
    allocating("the write counts of " + canvas_words(scene), pixel_count(scene) * 4,
               "the scene's canvas size or drop --counts", [&] { canvas.enable_write_counts(); });
  }
  Progress drawing = progress_of(args, "raster: drawing", scene.primitives.size(), err);
  const RenderStats stats =
      render_scene(scene, algorithm, canvas, [&](double done) { drawing.advance(done); });
  if (stats.rejected_triangles > 0) {
    throw std::runtime_error(std::to_string(stats.rejected_triangles) +
                             " triangle(s) have non-finite or out-of-range vertices");
  }
  // Both outputs replace their files together, or neither does.
  OutputTransaction files(&out);
  if (const auto path = args.value("out"))
    files.stage(*path, encode_png_saying_so(args, canvas, err));
  if (const auto path = args.value("counts")) {
    files.stage(*path, allocating("the counts PGM of " + canvas_words(scene), pixel_count(scene),
                                  "the scene's canvas size or drop --counts",
                                  [&] { return encode_counts_pgm(canvas); }));
  }
  files.commit();
  // With an image on standard output, the summary goes with the other messages.
  std::ostream& report = to_standard_output ? err : out;
  report << "drew " << stats.triangles << " triangle(s) and " << stats.lines << " line(s) on "
         << scene.width << "x" << scene.height;
  if (algorithm != nullptr) report << " with " << algorithm->name;
  if (format_arg) report << " as rgba8";
  report << '\n';
  return 0;
}

}  // namespace

int run_raster(std::span<const Drawable> drawables, int argc, const char* const* argv,
               std::ostream& out, std::ostream& err) {
  return run_command_line(raster_command_line(drawables), argc, argv, out, err,
                          [&](const CliArguments& args) { return run(drawables, args, out, err); });
}

int run_raster(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  return run_raster(registered_drawables(), argc, argv, out, err);
}

}  // namespace tri
