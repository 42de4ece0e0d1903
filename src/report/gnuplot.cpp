// Starting gnuplot as a child process and reporting its errors.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cic/report/plot.hpp"

namespace cic::app {

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

} // namespace cic::app
