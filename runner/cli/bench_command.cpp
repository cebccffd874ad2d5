#include <ctime>
#include <iostream>

#include "bench/cache_bench.h"
#include "bench/cascades_bench.h"
#include "bench/frontier_bench.h"
#include "bench/pipeline_bench.h"
#include "bench/pyramid_bench.h"
#include "bench/sweep_bench.h"
#include "bench/tables_bench.h"
#include "bench/traversal_bench.h"
#include "cli/commands.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/write_file.h"
#include "technique/technique_registry.h"

namespace pn::cli {

void add_bench_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::string what;
    std::vector<int> sizes{512, 1024, 2048};
    int repeats = 15;
    TraversalBenchSetup traversal;
    PipelineBenchSetup pipeline;
    SweepBenchSetup sweep;
    CacheBenchSetup cache;
    CascadesBenchSetup cascades;
    FrontierBenchSetup frontier;
    bool quick = false;
    std::vector<std::string> methods;
    int max_level = 31;
    std::string json;
    std::string plot;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("bench", "GPU timings (timestamp queries, medians) against baselines in the same run");
  cmd->add_option("what", opt->what, "pyramid | traversal | pipeline | sweep | frontier | cache | cascades | tables")->required();
  auto* sizes = cmd->add_option("--sizes", opt->sizes, "pyramid: shadow-map sizes N (default 512 1024 2048); tables: default 256 512 1024 2048 4096; pipeline, sweep: map = screen sizes (default 512 1024; sweep 512)")->delimiter(',');
  auto* repeats = cmd->add_option("--repeats", opt->repeats, "Timed runs (default 15 for pyramid, 5 for traversal, pipeline and tables, 3 for sweep)");
  cmd->add_option("--scene", opt->pipeline.scene, "pipeline: boxes | fence | tall_blocker (default boxes)");
  cmd->add_option("--model", opt->pipeline.model, "pipeline: a mesh file (any format Assimp reads) on the ground instead of --scene");
  auto* scenes = cmd->add_option("--scenes", opt->sweep.scenes, "sweep: scenes (default tall_blocker,boxes); frontier: default boxes,fence,tall_blocker,spider,city")->delimiter(',');
  auto* widths = cmd->add_option("--widths", opt->sweep.factors, "sweep, frontier: light width factors (default 1,2,4,8)")->delimiter(',');
  auto* exact_up_to = cmd->add_option("--exact-up-to", opt->sweep.exact_up_to, "sweep, frontier: run exact PCSS (frontier: and HQEPCSS) only at light width factors up to this (default 2; inf: at every factor)");
  cmd->add_flag("--quick", opt->quick, "frontier: the short run for CI (boxes and tall_blocker at 128², widths 1 and 8, a configuration per technique, one round)");
  cmd->add_option("--methods", opt->methods, "pipeline: techniques (default: every registry entry but fast-all-off); sweep: default exact,poisson,hqepcss,fast")->delimiter(',');
  auto* truth_samples = cmd->add_option("--truth-samples", opt->pipeline.truth_samples, "pipeline, sweep: S for the ray-traced truth's S x S light samples (default 16)");
  cmd->add_option("--max-level", opt->max_level, "pyramid: maximum level (default: all)");
  cmd->add_option("--map-size", opt->traversal.map_size, "traversal: shadow-map size (default 1024)");
  cmd->add_option("--receivers", opt->traversal.receivers, "traversal: receivers in the batch (default 4096)");
  cmd->add_option("--leaf-sizes", opt->traversal.leaf_sides, "traversal: leaf sizes (default 1,2,4,8,16)")->delimiter(',');
  cmd->add_option("--k", opt->cache.ks, "cache: shares K of moving triangles (default 0,0.1,...,1)")->delimiter(',');
  cmd->add_option("--sources", opt->cache.sources, "cache: shadow-map sources (default full,two-map,dirty-rect)")->delimiter(',');
  cmd->add_option("--frames", opt->cache.frames, "cache: timed frames per K (default 20, after --warmup untimed ones)");
  cmd->add_option("--warmup", opt->cache.warmup, "cache: untimed frames first (default 3)");
  auto* screen = cmd->add_option("--screen", opt->cache.screen, "cache: Fast PCSS's screen size (default 512); cascades: the screen (default 256)");
  cmd->add_option("--animated-scene", opt->cache.scene, "cache: moving_city | moving (default moving_city)");
  cmd->add_option("--counts", opt->cascades.counts, "cascades: split counts at --size (default 0,1,2,3,4; 0: one map over the scene)")->delimiter(',');
  cmd->add_option("--enlargements", opt->cascades.ks, "cascades: first-split enlargements k at --count, --size (default 1,2,4)")->delimiter(',');
  cmd->add_option("--count", opt->cascades.count, "cascades: the split count of the size and k sweeps and the path (default 3)");
  cmd->add_option("--size", opt->cascades.size, "cascades: the map size of the count and k sweeps and the path (default 1024)");
  cmd->add_option("--path-frames", opt->cascades.path_frames, "cascades: frames along the camera path (default 12)");
  cmd->add_option("--path-methods", opt->cascades.path_methods, "cascades: techniques along the camera path (default pcf,fast)")->delimiter(',');
  cmd->add_option("--json", opt->json, "Also write the results as JSON to this file");
  cmd->add_option("--plot", opt->plot, "cache: also draw the plot (time of the shadow-map stage, frame rate, against K) into this PNG; cascades, frontier: theirs");
  cmd->add_option("--glsl-root", global.glsl_root, "Benchmark the modules in this directory");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->callback([opt, repeats, sizes, truth_samples, screen, scenes, widths, exact_up_to, &global, &exit_code] {
    if (opt->what != "pyramid" && opt->what != "traversal" && opt->what != "pipeline" && opt->what != "sweep" &&
        opt->what != "frontier" && opt->what != "cache" && opt->what != "cascades" && opt->what != "tables")
      throw Error("bench '" + opt->what + "': expected one of pyramid, traversal, pipeline, sweep, frontier, cache, cascades, tables");
    if (opt->quick && opt->what != "frontier") throw Error("--quick: only bench frontier has a quick run");
    if (!opt->methods.empty()) require_list_length("methods", opt->methods.size());
    for (const std::string& spec : opt->methods) opt->pipeline.methods.push_back(parse_technique(spec));
    if (opt->what == "sweep") {  // bad input is reported before looking for a GL context
      opt->sweep.methods = opt->pipeline.methods;
      if (repeats->count() > 0) opt->sweep.repeats = opt->repeats;
      if (sizes->count() > 0) opt->sweep.sizes = opt->sizes;
      if (truth_samples->count() > 0) opt->sweep.truth_samples = opt->pipeline.truth_samples;
      validate_sweep_setup(opt->sweep);
    } else if (opt->what == "frontier") {
      if (opt->quick) opt->frontier = quick_frontier_setup();
      if (scenes->count() > 0) opt->frontier.scenes = opt->sweep.scenes;
      if (widths->count() > 0) opt->frontier.widths = opt->sweep.factors;
      if (sizes->count() > 0) opt->frontier.sizes = opt->sizes;
      if (repeats->count() > 0) opt->frontier.repeats = opt->repeats;
      if (truth_samples->count() > 0) opt->frontier.truth_samples = opt->pipeline.truth_samples;
      if (exact_up_to->count() > 0) opt->frontier.exact_up_to = opt->sweep.exact_up_to;
      if (!opt->methods.empty()) opt->frontier.methods = opt->methods;
      validate_frontier_setup(opt->frontier);
    } else if (opt->what == "cascades") {
      if (sizes->count() > 0) opt->cascades.sizes = opt->sizes;
      if (repeats->count() > 0) opt->cascades.repeats = opt->repeats;
      if (truth_samples->count() > 0) opt->cascades.truth_samples = opt->pipeline.truth_samples;
      if (!opt->methods.empty()) opt->cascades.methods = opt->methods;
      if (screen->count() > 0) opt->cascades.screen = opt->cache.screen;
      validate_cascades_bench_setup(opt->cascades);
    } else if (opt->what == "cache") {
      if (sizes->count() > 0) opt->cache.sizes = opt->sizes;
      if (!opt->pipeline.model.empty()) opt->cache.model = opt->pipeline.model;
      validate_cache_bench_setup(opt->cache);
    } else if (opt->what == "pipeline") {
      if (repeats->count() > 0) opt->pipeline.repeats = opt->repeats;
      if (sizes->count() > 0) opt->pipeline.sizes = opt->sizes;
      validate_pipeline_bench_setup(opt->pipeline);
    } else if (opt->what == "pyramid") {
      validate_pyramid_bench(opt->sizes, opt->repeats, opt->max_level);
    } else if (opt->what == "tables") {
      if (sizes->count() == 0) opt->sizes = {256, 512, 1024, 2048, 4096};
      if (repeats->count() == 0) opt->repeats = 5;
      validate_tables_bench(opt->sizes, opt->repeats);
    } else {
      if (repeats->count() > 0) opt->traversal.repeats = opt->repeats;
      validate_traversal_bench_setup(opt->traversal);
    }
    if (!opt->json.empty()) validate_output_path(opt->json);  // before the bench's minutes of work
    if (!opt->plot.empty() && opt->what != "cache" && opt->what != "cascades" && opt->what != "frontier")
      throw Error("--plot: only bench cache, cascades and frontier draw their plots (sweep: scripts/plot_sweep.py)");
    if (!opt->plot.empty()) validate_output_path(opt->plot);
    const SourceTree tree(glsl_root_or_default(global));
    const auto context = create_context(chosen_backend(global));
    std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer() << ", "
              << context->version() << "\n";
    nlohmann::json results;
    if (opt->what == "pyramid") {
      const auto rows = bench_pyramid(*context, tree, opt->sizes, opt->repeats, opt->max_level);
      print_pyramid_bench(std::cout, rows);
      results = pyramid_bench_json(rows);
    } else if (opt->what == "tables") {
      const auto rows = bench_tables(*context, tree, opt->sizes, opt->repeats);
      print_tables_bench(std::cout, rows);
      results = tables_bench_json(rows);
    } else if (opt->what == "sweep") {
      const SweepBench bench = bench_sweep(*context, tree, opt->sweep);
      print_sweep_bench(std::cout, bench);
      results = sweep_bench_json(opt->sweep, bench);
    } else if (opt->what == "frontier") {
      const std::vector<FrontierPoint> points = bench_frontier(*context, tree, opt->frontier);
      print_frontier_bench(std::cout, points);
      results = frontier_bench_json(opt->frontier, points);
      if (!opt->plot.empty()) {
        frontier_bench_chart(points, std::string("penumbra bench frontier") + (opt->quick ? " --quick" : "") +
                                         ": time against MAE vs the ray-traced truth, " + context->renderer())
            .write_png(opt->plot);
        std::cout << "wrote " << opt->plot << "\n";
      }
    } else if (opt->what == "cascades") {
      const CascadesBench bench = bench_cascades(*context, tree, opt->cascades);
      print_cascades_bench(std::cout, bench);
      results = cascades_bench_json(opt->cascades, bench);
      if (!opt->plot.empty()) {
        cascades_bench_chart(bench, "penumbra bench cascades: '" + bench.scene + "', " + std::to_string(bench.triangles) +
                                        " triangles, screen " + std::to_string(opt->cascades.screen) + "², " +
                                        context->renderer()).write_png(opt->plot);
        std::cout << "wrote " << opt->plot << "\n";
      }
    } else if (opt->what == "cache") {
      const CacheBench bench = bench_cache(*context, tree, opt->cache);
      print_cache_bench(std::cout, bench);
      results = cache_bench_json(opt->cache, bench);
      if (!opt->plot.empty()) {
        cache_bench_chart(bench, "penumbra bench cache: '" + bench.scene + "', " + std::to_string(bench.triangles) +
                                     " triangles, Fast PCSS at " + std::to_string(opt->cache.screen) + "², " +
                                     context->renderer()).write_png(opt->plot);
        std::cout << "wrote " << opt->plot << "\n";
      }
    } else if (opt->what == "pipeline") {
      const auto rows = bench_pipeline(*context, tree, opt->pipeline);
      print_pipeline_bench(std::cout, rows);
      results = pipeline_bench_json(opt->pipeline, rows);
    } else {
      const auto rows = bench_traversal(*context, tree, opt->traversal);
      print_traversal_bench(std::cout, opt->traversal, rows);
      results = traversal_bench_json(opt->traversal, rows);
    }
    if (!opt->json.empty()) {
      const std::time_t now = std::time(nullptr);
      char date[32];
      std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
      const nlohmann::json doc{{"bench", opt->what},
                               {"date", date},
                               {"backend", backend_name(context->backend())},
                               {"vendor", context->vendor()},
                               {"renderer", context->renderer()},
                               {"gl_version", context->version()},
                               {"results", results}};
      write_file_atomically(opt->json, doc.dump(2) + "\n");
    }
    exit_code = 0;
  });
}

}  // namespace pn::cli
