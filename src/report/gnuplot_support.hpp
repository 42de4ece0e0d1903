#pragma once
// Private to src/report: what every gnuplot figure needs (plot.cpp,
// archive_plot.cpp): a scratch folder, quoting, the terminal of the output's
// extension and running the script.
#include <filesystem>
#include <string>

namespace cic::report::detail {

// A scratch folder for the script and data files, removed afterwards.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// A gnuplot single-quoted string.
std::string quote(const std::string& s);
void write_file(const std::filesystem::path& path, const std::string& text);
// The terminal line for the output file's extension (.svg, .png, .pdf); throws
// cic::InputError for another extension.
std::string terminal_for(const std::filesystem::path& out_file, int width, int height, const std::string& gnuplot,
                         const std::filesystem::path& scratch);
// Throws cic::InputError when the output's folder does not exist.
void check_output_folder(const std::filesystem::path& out_file);
// Writes the script, runs gnuplot and checks that it wrote the output.
void render(const std::string& gnuplot, const std::filesystem::path& scratch, const std::string& script,
            const std::filesystem::path& out_file);

} // namespace cic::report::detail
