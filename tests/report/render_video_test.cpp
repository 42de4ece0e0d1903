// scripts/render-video.sh on a real R1 recording: POV-Ray frames become PNGs and an MP4.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "cic/report/preset_replay.hpp"
#include "cic/io/povray.hpp"
#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;

fs::path fresh_dir(const std::string& name) { return cic::testing::temp_dir("render-" + name); }

bool have(const char* tool) { return std::system(("command -v " + std::string(tool) + " >/dev/null 2>&1").c_str()) == 0; }

// A real R1 recording rendered by scripts/render-video.sh at 80x60: PNGs and an MP4 appear,
// and a frame is a picture, not one flat colour.
TEST(Povray, RenderScriptMakesFramesAndAVideo) {
    if (!have("povray") || !have("ffmpeg")) GTEST_SKIP() << "povray or ffmpeg not installed";
    report::PresetReplay preset;
    preset.sim.sample_to = 0.2;
    preset.sim.delayed_start = 0.0;
    const report::ReplayItem item = report::replay_preset(preset, 10.0, false);
    const fs::path dir = fresh_dir("render");
    io::PovrayOptions options;
    options.centre_body = item.centre_body;
    ASSERT_EQ(io::write_povray(item.recording, dir, 10.0, options), 3);

    const std::string script = std::string(CIC_SOURCE_DIR) + "/scripts/render-video.sh";
    const std::string cmd = "'" + script + "' '" + dir.string() + "' --width 80 --height 60 --fps 10 --jobs 2 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const fs::path png = dir / "frame_00000.png";
    ASSERT_TRUE(fs::exists(png));
    EXPECT_GT(fs::file_size(dir / "out.mp4"), 0u);

    // Decode the PNG with ffmpeg into raw RGB and count its colours.
    const std::string decode = "ffmpeg -loglevel error -i '" + png.string() + "' -f rawvideo -pix_fmt rgb24 -";
    FILE* pipe = popen(decode.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string pixels;
    char buf[4096];
    for (std::size_t got; (got = fread(buf, 1, sizeof buf, pipe)) > 0;) pixels.append(buf, got);
    ASSERT_EQ(pclose(pipe), 0);
    ASSERT_EQ(pixels.size(), 80u * 60u * 3u);
    std::set<std::string> colours;
    int orange = 0;
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        colours.insert(pixels.substr(i, 3));
        const auto r = static_cast<unsigned char>(pixels[i]), b = static_cast<unsigned char>(pixels[i + 2]);
        if (r > 80 && r > 2 * b) ++orange;
    }
    EXPECT_GT(colours.size(), 20u) << "a flat image";
    EXPECT_GT(orange, 10) << "no robot (chassis) pixels";

    // --overlay: the scenes' title and time written on the video: the first
    // frame's top-left corner differs from the same video without it.
    const auto first_frame = [&](const std::string& options) {
        const std::string render = "'" + script + "' '" + dir.string() + "' --width 160 --height 120 --fps 10 --jobs 2 " +
                                   options + " >/dev/null 2>&1";
        if (std::system(render.c_str()) != 0) return std::string();
        FILE* p = popen(("ffmpeg -loglevel error -i '" + (dir / "out.mp4").string() +
                         "' -frames:v 1 -f rawvideo -pix_fmt gray -").c_str(), "r");
        std::string out;
        for (std::size_t got; p && (got = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, got);
        if (p) pclose(p);
        return out;
    };
    const std::string plain = first_frame(""), with_text = first_frame("--overlay");
    ASSERT_EQ(plain.size(), 160u * 120u);
    ASSERT_EQ(with_text.size(), 160u * 120u);
    int changed = 0;   // in the top-left 100x30 pixels, where the two lines go
    for (int y = 5; y < 35; ++y)
        for (int x = 5; x < 105; ++x) {
            const std::size_t k = static_cast<std::size_t>(y * 160 + x);
            changed += std::abs(static_cast<int>(static_cast<unsigned char>(plain[k])) -
                                static_cast<int>(static_cast<unsigned char>(with_text[k]))) > 24;
        }
    EXPECT_GT(changed, 150) << "no overlay text in the corner";
    fs::remove_all(dir);
}

} // namespace
