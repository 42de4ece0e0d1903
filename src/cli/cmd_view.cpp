// `cic view`: only built with the viewer (CIC_WITH_VIEWER); see src/viz.
#ifdef CIC_HAVE_VIEWER
// `cic view`: watch replayed individuals in a window, or take an offscreen screenshot.
#include <unistd.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/core/error.hpp"
#include "cic/cli/commands.hpp"
#include "cic/run/self_path.hpp"
#include "cic/cli/replay_options.hpp"
#include "cic/viz/viewer.hpp"

namespace cic::cli {
namespace {

// Screenshots need an X server: without one, run this same command again inside
// xvfb-run (once; CIC_VIEW_UNDER_XVFB stops a loop). Returns only when that is impossible.
void reexec_under_xvfb() {
    if (std::getenv("DISPLAY") || std::getenv("CIC_VIEW_UNDER_XVFB")) return;
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) return;
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::vector<std::string> args;
    for (std::string arg; std::getline(in, arg, '\0');) args.push_back(arg);
    if (args.empty()) return;
    args[0] = run::self_path();   // this binary's file: under xvfb-run, /proc/self/exe would be its shell
    // -a takes the first free display from -n on; two views started at once from the
    // same number can both take it (xvfb-run checks, then starts), so each starts from
    // a number of its own process id.
    const std::string first_display = std::to_string(100 + getpid() % 10000);
    std::vector<std::string> cmd = {"xvfb-run", "-a", "-n", first_display, "-s", "-screen 0 1280x1024x24"};
    cmd.insert(cmd.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : cmd) argv.push_back(a.data());
    argv.push_back(nullptr);
    setenv("CIC_VIEW_UNDER_XVFB", "1", 1);
    std::cout.flush();
    std::cerr.flush();
    execvp("xvfb-run", argv.data());   // returns only on failure
}

viz::ViewEntry to_entry(report::ReplayItem& item) {
    viz::ViewEntry e;
    // The HUD shows "generation G | individual I", or the label alone (a preset
    // replay, or an archive's elite: "cell I,J,... (N), batch B").
    e.info.generation = item.elite ? -1 : item.generation;
    e.info.individual = item.generation >= 0 && !item.elite ? (item.who.empty() ? std::to_string(item.id) : item.who)
                                                            : item.label;
    e.info.fitness = item.replayed_fitness;
    e.recording = std::move(item.recording);
    e.centre_body = item.centre_body;
    e.preferred_axis = item.preferred_axis;
    return e;
}

} // namespace

void add_view_command(Command& app, CommandContext& ctx) {
    struct Options {
        report::ReplaySource source;
        int count = 5;
        std::string screenshot;
        double at = 5.0;
        int width = 0, height = 0;
        double speed = 1.0;
        double fps = 50.0;
        bool no_shadows = false;
        bool no_trail = false;
        std::string camera;
        std::vector<std::string> strip;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "view", "Replay individuals in a 3D window (space pause, r restart, +/- speed, n/p next/previous), "
                "or render one instant offscreen with --screenshot");
    add_replay_options(cmd, opts->source);
    cmd.option("--count", opts->count, "with --individual best: how many of the best to switch between")
        .show_default().positive();
    cmd.option("--screenshot", opts->screenshot, "write a PNG without opening a window (uses xvfb-run when "
                                                      "there is no X display)");
    cmd.option("--at", opts->at, "with --screenshot: seconds into the replay").show_default().non_negative();
    cmd.option("--width", opts->width, "pixels (default 1024, or 800 for a screenshot, 320 for each frame of a strip)").positive();
    cmd.option("--height", opts->height, "pixels (default 768, or 600 for a screenshot, 240 for a strip)").positive();
    cmd.option("--speed", opts->speed, "playback speed, 1 = real time (1/16 to 16)").show_default().range(1.0 / 16, 16.0);
    cmd.option("--fps", opts->fps, "recorded frames per second (interpolated in between)")
        .show_default().positive();
    cmd.flag("--no-shadows", opts->no_shadows, "draw without shadow mapping");
    cmd.flag("--no-trail", opts->no_trail,
             "draw no trail (default: the centre's path so far on the ground, a green ring at its start; key t)");
    cmd.option("--camera", opts->camera,
               "follow (the robot's centre) or fixed (on the world, framing the whole path); default: fixed for "
               "--screenshot, follow in the window (key c switches)");
    cmd.option("--strip", opts->strip,
               "with --screenshot: frames at these seconds side by side in one PNG (e.g. --strip 2,5,8), each "
               "--width wide")
        .delimiter(',');
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "view", [&] {
            if (!opts->camera.empty() && opts->camera != "follow" && opts->camera != "fixed")
                throw InputError("--camera takes follow or fixed; got '" + opts->camera + "'");
            if (!opts->strip.empty() && opts->screenshot.empty())
                throw InputError("--strip needs --screenshot FILE.png");
            std::vector<double> strip;
            for (const std::string& text : opts->strip) {
                std::size_t used = 0;
                double t = -1;
                try {
                    t = std::stod(text, &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used == 0 || used != text.size() || !std::isfinite(t) || t < 0)
                    throw InputError("--strip takes seconds >= 0, e.g. --strip 2,5,8; got '" + text + "'");
                strip.push_back(t);
            }
            if (opts->strip.size() > 64) throw InputError("--strip takes at most 64 times");
            if (!opts->screenshot.empty()) reexec_under_xvfb();
            else if (const char* d = std::getenv("DISPLAY"); !d || !*d)   // before the replays: they take seconds each
                throw std::runtime_error("no X display (DISPLAY is unset or empty): the window cannot open; "
                                         "use --screenshot FILE.png to render offscreen");
            const int count = opts->screenshot.empty() ? opts->count : 1;
            auto items = report::load_replay(opts->source, count, opts->fps, false);
            std::vector<viz::ViewEntry> entries;
            for (auto& item : items) {
                if (!ctx.quiet) {
                    std::cerr << fmt::format("{}: replayed fitness {:.6g}", item.label, item.replayed_fitness);
                    if (item.generation >= 0) std::cerr << fmt::format(" (stored {:.6g})", item.stored_fitness);
                    std::cerr << '\n';
                }
                if (item.generation >= 0 && std::fabs(item.replayed_fitness - item.stored_fitness) > 1e-9)
                    std::cerr << "warning: the replay differs from the stored fitness (settings or build changed?)\n";
                entries.push_back(to_entry(item));
            }
            if (!opts->screenshot.empty()) {
                viz::SceneOptions scene;
                scene.shadows = !opts->no_shadows;
                scene.trail = !opts->no_trail;
                scene.camera = opts->camera == "follow" ? viz::CameraMode::Follow : viz::CameraMode::Fixed;
                if (!strip.empty())
                    viz::screenshot_strip(entries.front(), strip, opts->width > 0 ? opts->width : 320,
                                          opts->height > 0 ? opts->height : 240, opts->screenshot, scene);
                else
                    viz::screenshot(entries.front(), opts->at, opts->width > 0 ? opts->width : 800,
                                    opts->height > 0 ? opts->height : 600, opts->screenshot, scene);
                if (!ctx.quiet) std::cerr << "wrote " << opts->screenshot << '\n';
                return 0;
            }
            viz::ViewerOptions view;
            if (opts->width > 0) view.width = opts->width;
            if (opts->height > 0) view.height = opts->height;
            view.speed = opts->speed;
            view.shadows = !opts->no_shadows;
            view.trail = !opts->no_trail;
            view.camera = opts->camera == "fixed" ? viz::CameraMode::Fixed : viz::CameraMode::Follow;
            view.window_title = "cic view";
            return viz::Viewer(std::move(entries), view).run();
        });
    });
}

} // namespace cic::cli

#endif  // CIC_HAVE_VIEWER
