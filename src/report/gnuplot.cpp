// Starting gnuplot as a child process and reporting its errors, and the
// helpers every figure's script shares (gnuplot_support.hpp).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/report/plot.hpp"
#include "gnuplot_support.hpp"

namespace cic::report {

namespace detail {

namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
    std::string templ = (fs::temp_directory_path() / "cic-plot-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw std::runtime_error("plot: cannot create a temporary folder");
    path_ = templ;
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

// A gnuplot single-quoted string.
std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out += '\'';
        out += c;
    }
    return out + "'";
}

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("plot: cannot write " + path.string());
}

// The terminal line for the output file's extension.
std::string terminal_for(const fs::path& out_file, int width, int height, const std::string& gnuplot,
                         const fs::path& scratch) {
    std::string ext = out_file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".svg")
        return fmt::format("set terminal svg size {},{} dynamic noenhanced font 'Sans,12' background rgb 'white'",
                           width, height);
    if (ext == ".pdf") {   // for papers: vector, fonts embedded; 96 pixels to the inch
        const fs::path probe = scratch / "probe.gp";
        write_file(probe, "set terminal pdfcairo\n");
        try {
            run_gnuplot(gnuplot, probe);
        } catch (const std::runtime_error&) {
            throw InputError("this gnuplot has no pdfcairo terminal for a .pdf (Debian: gnuplot-nox has it)",
                             out_file.string());
        }
        return fmt::format("set terminal pdfcairo size {:.3f}in,{:.3f}in noenhanced font 'Sans,9' background rgb 'white'",
                           width / 96.0, height / 96.0);
    }
    if (ext == ".png") {
        // pngcairo draws antialiased lines; plain png (libgd) is the fallback on minimal gnuplot builds.
        const fs::path probe = scratch / "probe.gp";
        write_file(probe, "set terminal pngcairo\n");
        try {
            run_gnuplot(gnuplot, probe);
            return fmt::format("set terminal pngcairo size {},{} noenhanced font 'Sans,10' background rgb 'white'",
                               width, height);
        } catch (const std::runtime_error&) {
            return fmt::format("set terminal png size {},{} noenhanced background rgb 'white'", width, height);
        }
    }
    throw InputError(fmt::format("unsupported plot format '{}' (use .svg, .png or .pdf)", ext), out_file.string());
}

void check_output_folder(const fs::path& out_file) {
    const fs::path parent = out_file.parent_path();
    if (!parent.empty() && !fs::is_directory(parent))
        throw InputError("output folder does not exist", parent.string());
}

void render(const std::string& gnuplot, const fs::path& scratch, const std::string& script,
            const fs::path& out_file) {
    const fs::path script_file = scratch / "plot.gp";
    write_file(script_file, script);
    std::error_code ec;
    fs::remove(out_file, ec);   // so a stale file cannot pass for a new plot
    run_gnuplot(gnuplot, script_file);
    if (!fs::exists(out_file) || fs::file_size(out_file) == 0)
        throw std::runtime_error("gnuplot exited normally but wrote no " + out_file.string());
}

} // namespace detail


void run_gnuplot(const std::string& gnuplot, const std::filesystem::path& script_file) {
    const std::filesystem::path err_file = script_file.string() + ".err";
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("gnuplot: fork failed");
    if (pid == 0) {
        const int fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDERR_FILENO);
            dup2(fd, STDOUT_FILENO);
            ::close(fd);
        }
        const std::string script = script_file.string();
        execlp(gnuplot.c_str(), gnuplot.c_str(), script.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw std::runtime_error("gnuplot: waitpid failed");
    }
    std::ostringstream err;
    err << std::ifstream(err_file).rdbuf();
    std::error_code ec;
    std::filesystem::remove(err_file, ec);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        throw std::runtime_error(fmt::format("cannot start '{}' (install gnuplot, e.g. apt-get install gnuplot-nox)",
                                             gnuplot));
    throw std::runtime_error(fmt::format("{} failed ({}) on {}:\n{}", gnuplot,
                                         WIFEXITED(status) ? fmt::format("exit code {}", WEXITSTATUS(status))
                                                           : std::string("killed by a signal"),
                                         script_file.string(), err.str()));
}

} // namespace cic::report
