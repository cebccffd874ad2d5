#include <algorithm>
#include <ctime>
#include <iostream>

#include "bench/cache_bench.h"
#include "bench/cascades_bench.h"
#include "bench/frontier_bench.h"
#include "bench/frontier_goal.h"
#include "bench/pipeline_bench.h"
#include "bench/pyramid_bench.h"
#include "bench/sweep_bench.h"
#include "bench/tables_bench.h"
#include "bench/traversal_bench.h"
#include "cli/commands.h"
#include "core/utf8.h"
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
    std::vector<std::string> techniques;
    int max_level = 31;
    std::string json;
    std::string plot;
    std::string goal_plot;
    std::string estimate = "navi21";
  };
  auto opt = std::make_shared<Options>();
  // Which benches read each option (issue 26 B18): one given to a bench that does not is refused.
  auto applies = std::make_shared<std::vector<std::pair<CLI::Option*, std::vector<std::string>>>>();
  const auto applies_to = [applies](CLI::Option* option, std::vector<std::string> whats) {
    applies->emplace_back(option, std::move(whats));
    return option;
  };
  auto* cmd = app.add_subcommand("bench", "GPU timings (timestamp queries, medians) against baselines in the same run");
  cmd->add_option("what", opt->what, "pyramid | traversal | pipeline | sweep | frontier | cache | cascades | tables")->required();
  auto* sizes = applies_to(cmd->add_option("--sizes", opt->sizes, "pyramid: shadow-map sizes N (default 512 1024 2048); tables: default 256 512 1024 2048 4096; pipeline, sweep: map = screen sizes (default 512 1024; sweep 512)")->delimiter(','), {"pyramid", "pipeline", "sweep", "frontier", "cache", "cascades", "tables"});
  auto* repeats = applies_to(cmd->add_option("--repeats", opt->repeats, "Timed runs (default 15 for pyramid, 5 for traversal, pipeline and tables, 3 for sweep)"), {"pyramid", "traversal", "pipeline", "sweep", "frontier", "cascades", "tables"});
  applies_to(cmd->add_option("--scene", opt->pipeline.scene, "pipeline: boxes | fence | tall_blocker (default boxes)"), {"pipeline"});
  applies_to(cmd->add_option("--model", opt->pipeline.model, "pipeline: a mesh file (any format Assimp reads) on the ground instead of --scene; sweep, frontier: the one scene, instead of --scenes; cache: the animated scene's model"), {"pipeline", "cache", "sweep", "frontier"});
  auto* scenes = applies_to(cmd->add_option("--scenes", opt->sweep.scenes, "sweep: scenes (default tall_blocker,boxes); frontier: default boxes,fence,tall_blocker,spider,city")->delimiter(','), {"sweep", "frontier"});
  auto* widths = applies_to(cmd->add_option("--widths", opt->sweep.factors, "sweep, frontier: light width factors (default 1,2,4,8)")->delimiter(','), {"sweep", "frontier"});
  auto* exact_up_to = applies_to(cmd->add_option("--exact-up-to", opt->sweep.exact_up_to, "sweep, frontier: run exact PCSS (frontier: and HQEPCSS) only at light width factors up to this (default 2; inf: at every factor)"), {"sweep", "frontier"});
  applies_to(cmd->add_flag("--quick", opt->quick, "frontier: the short run for CI (boxes and tall_blocker at 128² and 256², widths 1 and 4, a configuration per technique family, one round)"), {"frontier"});
  applies_to(cmd->add_option("--techniques", opt->techniques, "pipeline: techniques (default: every registry entry but fast-all-off); sweep: default exact,poisson,hqepcss,fast")->delimiter(','), {"pipeline", "sweep", "frontier", "cascades"});
  auto* truth_samples = applies_to(cmd->add_option("--truth-samples", opt->pipeline.truth_samples, "pipeline, sweep: S for the ray-traced truth's S x S light samples (default 16)"), {"pipeline", "sweep", "frontier", "cascades"});
  applies_to(cmd->add_option("--max-level", opt->max_level, "pyramid: maximum level (default: all)"), {"pyramid"});
  applies_to(cmd->add_option("--map-size", opt->traversal.map_size, "traversal: shadow-map size (default 1024)"), {"traversal"});
  applies_to(cmd->add_option("--receivers", opt->traversal.receivers, "traversal: receivers in the batch (default 4096)"), {"traversal"});
  applies_to(cmd->add_option("--leaf-sizes", opt->traversal.leaf_sides, "traversal: leaf sizes (default 1,2,4,8,16)")->delimiter(','), {"traversal"});
  applies_to(cmd->add_option("--k", opt->cache.ks, "cache: shares K of moving triangles (default 0,0.1,...,1)")->delimiter(','), {"cache"});
  applies_to(cmd->add_option("--sources", opt->cache.sources, "cache: shadow-map sources (default full,two-map,dirty-rect)")->delimiter(','), {"cache"});
  applies_to(cmd->add_option("--frames", opt->cache.frames, "cache: timed frames per K (default 20, after --warmup untimed ones)"), {"cache"});
  applies_to(cmd->add_option("--warmup", opt->cache.warmup, "cache: untimed frames first (default 3)"), {"cache"});
  auto* screen = applies_to(cmd->add_option("--screen", opt->cache.screen, "cache: Fast PCSS's screen size (default 512); cascades: the screen (default 256); frontier: the screen (default: the map's size)"), {"cache", "cascades", "frontier"});
  applies_to(cmd->add_option("--animated-scene", opt->cache.scene, "cache: moving_city | moving (default moving_city)"), {"cache"});
  applies_to(cmd->add_option("--counts", opt->cascades.counts, "cascades: split counts at --size (default 0,1,2,3,4; 0: one map over the scene)")->delimiter(','), {"cascades"});
  applies_to(cmd->add_option("--enlargements", opt->cascades.ks, "cascades: first-split enlargements k at --count, --size (default 1,2,4)")->delimiter(','), {"cascades"});
  applies_to(cmd->add_option("--count", opt->cascades.count, "cascades: the split count of the size and k sweeps and the path (default 3)"), {"cascades"});
  applies_to(cmd->add_option("--size", opt->cascades.size, "cascades: the map size of the count and k sweeps and the path (default 1024)"), {"cascades"});
  applies_to(cmd->add_option("--path-frames", opt->cascades.path_frames, "cascades: frames along the camera path (default 12)"), {"cascades"});
  applies_to(cmd->add_option("--path-techniques", opt->cascades.path_techniques, "cascades: techniques along the camera path (default pcf,fast)")->delimiter(','), {"cascades"});
  auto* estimate = applies_to(cmd->add_option("--estimate", opt->estimate, "pipeline, sweep, frontier: the GPU cost estimate beside each time for this RADV family, FAMILY/32 for wave32 (default navi21; off: none; docs/isa.md)"), {"pipeline", "sweep", "frontier"});
  cmd->add_option("--json", opt->json, "Also write the results as JSON to this file");
  applies_to(cmd->add_option("--plot", opt->plot, "cache: also draw the plot (time of the shadow-map stage, frame rate, against K) into this PNG; cascades, frontier: theirs"), {"cache", "cascades", "frontier"});
  applies_to(cmd->add_option("--goal-plot", opt->goal_plot, "frontier: issue 52's panels alone into this PNG (fast's and the unbounded walk's estimate / Poisson's against the width; needs fast, poisson and the estimate)"), {"frontier"});
  cmd->add_option("--glsl-root", global.glsl_root, "Benchmark the modules in this directory");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->callback([opt, applies, repeats, sizes, truth_samples, screen, scenes, widths, exact_up_to, estimate, &global, &exit_code] {
    // sweep and frontier: the model on the ground is the one scene, named by its stem.
    const auto model_scenes = [&](std::vector<std::string>& names, std::filesystem::path& model) {
      if (opt->pipeline.model.empty()) return;
      if (scenes->count() > 0)
        throw Error("--model: bench " + opt->what + " puts the model on the ground as its one scene; expected --model or --scenes, not both");
      model = opt->pipeline.model;
      names = {model.stem().string()};
    };
    if (opt->what != "pyramid" && opt->what != "traversal" && opt->what != "pipeline" && opt->what != "sweep" &&
        opt->what != "frontier" && opt->what != "cache" && opt->what != "cascades" && opt->what != "tables")
      throw Error("bench '" + opt->what + "': expected one of pyramid, traversal, pipeline, sweep, frontier, cache, cascades, tables");
    for (const auto& [option, whats] : *applies) {
      if (option->count() == 0 || std::find(whats.begin(), whats.end(), opt->what) != whats.end()) continue;
      std::string list;
      for (const std::string& w : whats) list += (list.empty() ? "bench " : ", bench ") + w;
      throw Error(option->get_name() + ": bench " + opt->what + " does not use it (it applies to " + list + ")");
    }
    if (!opt->techniques.empty()) require_list_length("techniques", opt->techniques.size());
    for (const std::string& technique : opt->techniques) opt->pipeline.techniques.push_back(parse_technique(technique));
    if (opt->what == "sweep") {  // bad input is reported before looking for a GL context
      opt->sweep.techniques = opt->pipeline.techniques;
      if (estimate->count() > 0) opt->sweep.estimate = parse_gpu_estimate(opt->estimate);
      if (repeats->count() > 0) opt->sweep.repeats = opt->repeats;
      if (sizes->count() > 0) opt->sweep.sizes = opt->sizes;
      if (truth_samples->count() > 0) opt->sweep.truth_samples = opt->pipeline.truth_samples;
      model_scenes(opt->sweep.scenes, opt->sweep.model);
      validate_sweep_setup(opt->sweep);
    } else if (opt->what == "frontier") {
      if (opt->quick) opt->frontier = quick_frontier_setup();
      if (estimate->count() > 0) opt->frontier.estimate = parse_gpu_estimate(opt->estimate);
      if (scenes->count() > 0) opt->frontier.scenes = opt->sweep.scenes;
      if (widths->count() > 0) opt->frontier.widths = opt->sweep.factors;
      if (sizes->count() > 0) opt->frontier.sizes = opt->sizes;
      if (repeats->count() > 0) opt->frontier.repeats = opt->repeats;
      if (truth_samples->count() > 0) opt->frontier.truth_samples = opt->pipeline.truth_samples;
      if (exact_up_to->count() > 0) opt->frontier.exact_up_to = opt->sweep.exact_up_to;
      if (screen->count() > 0) opt->frontier.screen = opt->cache.screen;
      if (!opt->techniques.empty()) opt->frontier.techniques = opt->techniques;
      model_scenes(opt->frontier.scenes, opt->frontier.model);
      validate_frontier_setup(opt->frontier);
      if (!opt->goal_plot.empty()) require_goal_inputs(opt->frontier);
    } else if (opt->what == "cascades") {
      if (sizes->count() > 0) opt->cascades.sizes = opt->sizes;
      if (repeats->count() > 0) opt->cascades.repeats = opt->repeats;
      if (truth_samples->count() > 0) opt->cascades.truth_samples = opt->pipeline.truth_samples;
      if (!opt->techniques.empty()) opt->cascades.techniques = opt->techniques;
      if (screen->count() > 0) opt->cascades.screen = opt->cache.screen;
      validate_cascades_bench_setup(opt->cascades);
    } else if (opt->what == "cache") {
      if (sizes->count() > 0) opt->cache.sizes = opt->sizes;
      if (!opt->pipeline.model.empty()) opt->cache.model = opt->pipeline.model;
      validate_cache_bench_setup(opt->cache);
    } else if (opt->what == "pipeline") {
      if (estimate->count() > 0) opt->pipeline.estimate = parse_gpu_estimate(opt->estimate);
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
    if (!opt->json.empty()) probe_output_file(opt->json);  // before the bench's minutes of work
    if (!opt->json.empty() && !valid_utf8(opt->pipeline.model.string()))  // JSON holds UTF-8 only (issue 26 B11)
      throw Error("--model '" + opt->pipeline.model.string() + "': the path is not UTF-8, which --json cannot record; "
                  "expected a UTF-8 path (rename the file) or no --json");
    if (!opt->plot.empty()) probe_output_file(opt->plot);
    if (!opt->goal_plot.empty()) probe_output_file(opt->goal_plot);
    require_distinct_outputs({{"--json", opt->json}, {"--plot", opt->plot}, {"--goal-plot", opt->goal_plot}});  // issue 39 C11
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
      print_frontier_bench(std::cout, points, opt->frontier.estimate);
      results = frontier_bench_json(opt->frontier, points);
      if (!opt->plot.empty()) {
        frontier_bench_chart(points, std::string("penumbra bench frontier") + (opt->quick ? " --quick" : "") +
                                         ": time against MAE vs the ray-traced truth, " + context->renderer(),
                             opt->frontier.estimate)
            .write_png(opt->plot);
        std::cout << "wrote " << opt->plot << "\n";
      }
      if (!opt->goal_plot.empty()) {
        frontier_goal_chart(points, "penumbra bench frontier: fast's GPU estimate / Poisson 36/64's against the light's "
                                    "width, with and without its work budget (" + gpu_estimate_label(*opt->frontier.estimate) + ")")
            .write_png(opt->goal_plot);
        std::cout << "wrote " << opt->goal_plot << "\n";
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
      print_pipeline_bench(std::cout, rows, opt->pipeline.estimate);
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
      // Any other text that is not UTF-8 (a driver's string) is written as U+FFFD, never an error.
      write_file_atomically(opt->json, doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    exit_code = 0;
  });
}

}  // namespace pn::cli
