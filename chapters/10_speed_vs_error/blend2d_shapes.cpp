#include "chapters/10_speed_vs_error/blend2d_shapes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/10_speed_vs_error/coverage_measure.hpp"
#include "chapters/10_speed_vs_error/measure.hpp"
#include "chapters/10_speed_vs_error/report_csv.hpp"
#include "measure/area_error.hpp"

namespace tri::ch10 {

Blend2dShapesSettings blend2d_shapes_settings(SuiteSize size) {
  switch (size) {
    case SuiteSize::tiny:
      return {4, {0.0, 1, 1}, 1};  // one run, one sample: the tests check the form only
    case SuiteSize::quick:
      return {100, {0.005, 3, 1 << 20}, 4};  // short samples: a part of the quick run, not its bulk
    case SuiteSize::full:
      return {1000, {0.02, 7, 1 << 22}, 16};
  }
  return blend2d_shapes_settings(SuiteSize::quick);
}

SuiteScene blend2d_shape_scene(int box_side, int triangles) {
  const SceneRecipe recipe{
      .kind = SceneRecipe::Kind::in_boxes,
      .width = blend2d_canvas_width,
      .height = blend2d_canvas_height,
      .triangles = triangles,
      .box_side = static_cast<double>(box_side),
      .grid_bits = 8,
      .seed = 9100 + static_cast<std::uint64_t>(box_side)};  // the report's own
  return {std::to_string(box_side) + "x" + std::to_string(box_side), "1/256", recipe, false};
}

namespace {

// Each way of writing in ShapeWrites's order: its name, and bl_bench's composition operator.
struct WritesNames {
  std::string_view name;
  std::string_view comp_op;
};
constexpr std::array<WritesNames, 4> writes_names{
    {{"replace", "SrcCopy"}, {"add", "Plus"}, {"over", "SrcOver"}, {"peer", "Peer"}}};

const WritesNames& names_of(ShapeWrites writes) noexcept {
  return writes_names[static_cast<std::size_t>(writes)];
}

}  // namespace

std::string_view writes_name(ShapeWrites writes) noexcept {
  return names_of(writes).name;
}

double ShapeRate::calls_per_ms() const noexcept {
  const double seconds = timing.seconds.median;
  return seconds > 0 ? static_cast<double>(triangles) / (seconds * 1000) : 0.0;
}

std::vector<ShapeRate> run_blend2d_shapes(std::span<const TriangleAlgorithm> algorithms,
                                          std::span<const ExternalPeer> peers,
                                          std::span<const ch09::AreaAlgorithm> area_algorithms,
                                          std::span<const CoveragePeer> coverage_peers,
                                          const Blend2dShapesSettings& settings,
                                          std::ostream& progress) {
  std::vector<ShapeRate> rows;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t total =
      blend2d_box_sides.size() *
      (algorithms.size() + peers.size() + area_algorithms.size() + coverage_peers.size());
  for (const int side : blend2d_box_sides) {
    const PreparedScene prepared =
        prepare_scene(blend2d_shape_scene(side, settings.triangles), settings.error_triangle_limit);
    const auto record = [&](std::string_view drawer, std::string_view chapter, ShapeWrites writes,
                            const Timing& timing) {
      rows.push_back({std::string(drawer), std::string(chapter), writes, side,
                      prepared.triangles.size(), timing});
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char line[256];
      std::snprintf(line, sizeof line, "[%3zu/%zu] %-8s %-7s %-28s %10.4g calls/ms  (%.1f s)",
                    rows.size(), total, prepared.suite.name.c_str(),
                    std::string(writes_name(writes)).c_str(), rows.back().drawer.c_str(),
                    rows.back().calls_per_ms(), elapsed);
      progress << line << std::endl;  // flushed: the line is the progress
    };
    const std::vector<Timing> timings = time_algorithms(algorithms, prepared, settings.timing);
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      record(algorithms[i].name, algorithms[i].chapter, ShapeWrites::replace, timings[i]);
    }
    const std::vector<Timing> area_timings =
        time_area_algorithms(area_algorithms, prepared, settings.timing);
    for (std::size_t i = 0; i < area_algorithms.size(); ++i) {
      const ch09::AreaAlgorithm& a = area_algorithms[i];
      record(a.name, a.chapter, a.composites_over ? ShapeWrites::over : ShapeWrites::add,
             area_timings[i]);
    }
    for (const ExternalPeer& peer : peers) {
      // Only the draw when the peer can time it alone; else its whole measurement's timing.
      const Timing timing = peer.time ? peer.time(prepared, settings.timing)
                                      : peer.measure(prepared, settings.timing).timing;
      record(peer.name, peer.chapter, ShapeWrites::peer, timing);
    }
    if (!coverage_peers.empty()) {
      const AreaTruth truth(prepared.error_scene);  // its error comes with its time
      for (const CoveragePeer& peer : coverage_peers) {
        record(peer.name, peer.chapter, ShapeWrites::peer,
               peer.measure(prepared, truth, settings.timing).timing);
      }
    }
  }
  return rows;
}

std::string host_instruction_set() {
  // A switch without default: a set added to InstructionSet must be named here too.
  switch (ch08::widest_instruction_set()) {
    case ch08::InstructionSet::portable:
      return "SSE2 (portable)";
    case ch08::InstructionSet::avx2:
      return "AVX2";
  }
  return "unknown";
}

namespace {

// The drawers in the order they first appear, with their rows in size order.
struct DrawerRates {
  const ShapeRate* first = nullptr;
  std::vector<const ShapeRate*> by_size;  // one per size of blend2d_box_sides, null if missing
};

std::vector<DrawerRates> by_drawer(std::span<const ShapeRate> rows) {
  std::vector<DrawerRates> drawers;
  for (const ShapeRate& row : rows) {
    auto it = std::find_if(drawers.begin(), drawers.end(),
                           [&](const DrawerRates& d) { return d.first->drawer == row.drawer; });
    if (it == drawers.end()) {
      drawers.push_back({&row, std::vector<const ShapeRate*>(blend2d_box_sides.size(), nullptr)});
      it = std::prev(drawers.end());
    }
    const auto size = std::find(blend2d_box_sides.begin(), blend2d_box_sides.end(), row.box_side);
    if (size != blend2d_box_sides.end()) it->by_size[size - blend2d_box_sides.begin()] = &row;
  }
  return drawers;
}

// bl_bench's own formatting of a rate (its DurationFormat): more decimals for smaller numbers.
std::string bl_bench_number(double calls_per_ms) {
  char text[64];
  if (calls_per_ms <= 0.1) {
    std::snprintf(text, sizeof text, "%0.4f", calls_per_ms);
  } else if (calls_per_ms <= 1.0) {
    std::snprintf(text, sizeof text, "%0.3f", calls_per_ms);
  } else if (calls_per_ms < 10.0) {
    std::snprintf(text, sizeof text, "%0.2f", calls_per_ms);
  } else if (calls_per_ms < 100.0) {
    std::snprintf(text, sizeof text, "%0.1f", calls_per_ms);
  } else {
    std::snprintf(text, sizeof text, "%.0f", std::round(calls_per_ms));
  }
  return text;
}

// A JSON string: quotes, backslashes and control characters escaped.
std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string size_label(int side) {
  return std::to_string(side) + "x" + std::to_string(side);
}

std::string architecture() {
#if defined(__x86_64__)
  return "x86_64";
#elif defined(__aarch64__)
  return "aarch64";
#elif defined(__wasm__)
  return "wasm";
#else
  return "unknown";
#endif
}

}  // namespace

std::string blend2d_shapes_csv(std::span<const ShapeRate> rows) {
  constexpr std::string_view header =
      "drawer,chapter,writes,box_side,canvas,triangles,repetitions,samples,median_s,min_s,"
      "max_s,calls_per_ms";
  return csv_table(header, rows, [](const ShapeRate& r) {
    return std::tuple(r.drawer, r.chapter, writes_name(r.writes), r.box_side,
                      canvas_column(blend2d_canvas_width, blend2d_canvas_height), r.triangles,
                      r.timing.repetitions, r.timing.samples, seconds_columns(r.timing),
                      r.calls_per_ms());
  });
}

std::string blend2d_shapes_markdown(std::span<const ShapeRate> rows, const Machine& machine) {
  if (rows.empty()) return "";
  std::ostringstream md;
  md << "\n## Blend2D's benchmark shapes\n\n"
     << "Blend2D's `bl_bench` FillTriangle test: each triangle is three random points in an N×N "
        "square placed at random on a "
     << blend2d_canvas_width << "×" << blend2d_canvas_height << " canvas (vertices on the 1/256 "
     << "grid), " << rows.front().triangles << " triangles per size, one colour each. Render "
     << "calls per millisecond, one triangle being one call (the book's drawers and pixman take "
        "a frame's triangles in one call, the others one call each); "
     << machine.cpu_model
     << ", one thread unless the drawer is threaded, vector copies: " << host_instruction_set()
     << ". Every rate is in `" << blend2d_shapes_csv_file_name
     << "`, and in `bl_bench`'s JSON layout in `" << blend2d_shapes_json_file_name << "`.\n\n"
     << "| drawer | chapter | writes |";
  for (const int side : blend2d_box_sides) md << ' ' << size_label(side) << " |";
  md << "\n|---|---|---|";
  for (std::size_t i = 0; i < blend2d_box_sides.size(); ++i) md << "--:|";
  md << '\n';
  bool blends = false;
  for (const DrawerRates& d : by_drawer(rows)) {
    blends = blends || d.first->writes == ShapeWrites::over;
    md << "| " << d.first->drawer << " | " << d.first->chapter << " | "
       << writes_name(d.first->writes) << " |";
    for (const ShapeRate* r : d.by_size)
      md << ' ' << (r ? bl_bench_number(r->calls_per_ms()) : "–") << " |";
    md << '\n';
  }
  md << "\nWrites: *replace* puts the colour in the pixel (bl_bench's SrcCopy), *add* adds the "
        "coverage to it (Plus), *over* composites the coverage as alpha (SrcOver), *peer* is the "
        "peer's own way, as in the parts above. Blending (over) is "
     << (blends ? "measured for the coverage algorithms that composite; "
                : "not measured in this run; ")
     << "the aliased algorithms only replace and the summing coverage algorithms only add, so "
        "their blending is not measured.\n";
  return md.str();
}

std::string bl_bench_json(std::span<const ShapeRate> rows, const Machine& machine) {
  const std::vector<DrawerRates> drawers = by_drawer(rows);
  std::ostringstream json;
  json << "{\n"
       << "  \"environment\": {\"os\": \"linux\"},\n"
       << "  \"cpu\": {\"arch\": " << json_string(architecture())
       << ", \"brand\": " << json_string(machine.cpu_model)
       << ", \"instructionSet\": " << json_string(host_instruction_set()) << "},\n"
       << "  \"screen\": {\"width\": " << blend2d_canvas_width
       << ", \"height\": " << blend2d_canvas_height << ", \"format\": \"rgba8, coverage16\"},\n"
       << "  \"options\": {\"quantity\": " << (rows.empty() ? 0 : rows.front().triangles)
       << ", \"sizes\": [";
  for (std::size_t i = 0; i < blend2d_box_sides.size(); ++i) {
    json << (i ? ", " : "") << '"' << size_label(blend2d_box_sides[i]) << '"';
  }
  json << "], \"repeat\": " << (rows.empty() ? 0 : rows.front().timing.samples) << "},\n"
       << "  \"runs\": [";
  for (std::size_t i = 0; i < drawers.size(); ++i) {
    const ShapeRate& first = *drawers[i].first;
    json << (i ? "," : "") << "\n    {\"name\": " << json_string(first.drawer)
         << ", \"chapter\": " << json_string(first.chapter) << ", \"records\": [\n"
         << "      {\"test\": \"FillTriangle\", \"compOp\": "
         << json_string(names_of(first.writes).comp_op) << ", \"style\": \"Solid\", \"rcpms\": [";
    for (std::size_t s = 0; s < drawers[i].by_size.size(); ++s) {
      const ShapeRate* r = drawers[i].by_size[s];
      json << (s ? ", " : "") << (r ? bl_bench_number(r->calls_per_ms()) : "null");
    }
    json << "]}\n    ]}";
  }
  json << "\n  ]\n}\n";
  return json.str();
}

}  // namespace tri::ch10
