#pragma once
// Error types shared by every layer. Input errors carry where they came from
// so that messages can name file, line and element (see io/).
#include <stdexcept>
#include <string>

namespace cic {

// Bad user input: a settings key, a population file, a robot file, a tree text.
// what() is the full one-line message; the fields let tests and callers look closer.
class InputError : public std::runtime_error {
public:
    InputError(std::string message, std::string file = {}, int line = 0)
        : std::runtime_error(compose(message, file, line)),
          file_(std::move(file)), line_(line), message_(std::move(message)) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& message() const { return message_; }

private:
    static std::string compose(const std::string& m, const std::string& f, int line) {
        if (f.empty()) return m;
        return f + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + m;
    }
    std::string file_;
    int line_;
    std::string message_;
};

// A batch stopped on request (PoolOptions::interrupted): no result, no worker left.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted") {}
};

} // namespace cic
