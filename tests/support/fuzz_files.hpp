#pragma once
// The fuzz targets' files as the regression tests replay them
// (tests/io/fuzz_regression_test.cpp, tests/study/fuzz_study_regression_test.cpp):
// fuzz/corpus/<target>/ holds the seeds, fuzz/regressions/<target>/ the reproducers.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cic::testing {

inline const std::filesystem::path& fuzz_folder() {
    static const std::filesystem::path dir = std::filesystem::path(CIC_SOURCE_DIR) / "fuzz";
    return dir;
}

inline std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The files of fuzz/<kind>/<target>/, sorted (none if the folder is missing).
inline std::vector<std::filesystem::path> fuzz_files(const std::string& kind, const std::string& target) {
    std::vector<std::filesystem::path> out;
    const std::filesystem::path dir = fuzz_folder() / kind / target;
    if (!std::filesystem::is_directory(dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// The reproducers of an issue (fuzz/regressions/<target>/<prefix>*, e.g.
// "issue39-"), each of which a reader believed, or refused badly, before its fix.
inline std::vector<std::filesystem::path> issue_inputs(const std::string& target, const std::string& prefix) {
    std::vector<std::filesystem::path> out;
    for (const auto& f : fuzz_files("regressions", target))
        if (f.filename().string().rfind(prefix, 0) == 0) out.push_back(f);
    return out;
}

// The reproducers of issue 24 (fuzz/regressions/<target>/issue24-*), each of
// which a reader accepted, or refused without a line, before the fix.
inline std::vector<std::filesystem::path> issue24_inputs(const std::string& target) {
    return issue_inputs(target, "issue24-");
}

} // namespace cic::testing
