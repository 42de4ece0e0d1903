// `cic eval --settings FILE`: a JSON-lines stream for any language. Each line
// of standard input is one genotype; each gets one line of results on standard
// output, in order. The protocol is stable (docs/python.md, "The stream").
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cic/cli/commands.hpp"
#include "cic/core/error.hpp"
#include "cic/run/evaluation_session.hpp"
#include "cic/run/self_path.hpp"
#include "cic/sim/evaluate.hpp"

namespace cic::cli {

namespace {

using nlohmann::json;

constexpr int kProtocol = 1;

struct EvalOptions {
    std::string settings;
    std::vector<std::string> overrides;
    int workers = 1;
    int batch = 64;
    bool info = false;
};

// Lines of standard input: blocks for the first, then takes those already
// waiting (up to `most`), so a client that writes one line and waits for its
// answer is answered at once, and one that streams many fills the workers.
class LineReader {
public:
    // false at the end of input with nothing read.
    bool next_batch(std::vector<std::string>& lines, std::size_t most) {
        lines.clear();
        while (lines.size() < most) {
            if (take_line(lines)) continue;
            if (eof_) break;
            if (!lines.empty() && !ready()) break;
            if (!fill()) eof_ = true;
        }
        if (eof_ && !buffer_.empty() && lines.size() < most) {   // a last line without its newline
            lines.push_back(buffer_);
            buffer_.clear();
        }
        return !lines.empty();
    }

private:
    bool take_line(std::vector<std::string>& lines) {
        const std::size_t eol = buffer_.find('\n');
        if (eol == std::string::npos) return false;
        lines.push_back(buffer_.substr(0, eol));
        buffer_.erase(0, eol + 1);
        return true;
    }
    static bool ready() {
        pollfd p{0, POLLIN, 0};
        return ::poll(&p, 1, 0) > 0;
    }
    bool fill() {
        char chunk[65536];
        for (;;) {
            const ssize_t n = ::read(0, chunk, sizeof chunk);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            buffer_.append(chunk, static_cast<std::size_t>(n));
            return true;
        }
    }
    std::string buffer_;
    bool eof_ = false;
};

// A line's genotype: {"genotype": G, "offsets": [D...], "id": ANY} or G alone,
// where G is an array of numbers (a gait or CPG vector), an S-expression string,
// or an array of them (a forest), and "offsets" Offset-HybrID's per-hinge direct
// genes beside a forest. Throws InputError for anything else.
run::Genotype genotype_of(const json& line) {
    const json& g = line.is_object() ? line.at("genotype") : line;
    run::Genotype out;
    if (line.is_object() && line.contains("offsets")) {
        const json& d = line.at("offsets");
        if (!d.is_array()) throw InputError("\"offsets\" is an array of numbers (Offset-HybrID's, one per hinge)");
        for (const json& v : d) {
            if (!v.is_number()) throw InputError("\"offsets\" is an array of numbers (Offset-HybrID's, one per hinge)");
            out.offsets.push_back(v.get<double>());
        }
    }
    if (g.is_string()) {
        out.trees.push_back(g.get<std::string>());
    } else if (g.is_array() && !g.empty() && g.front().is_string()) {
        for (const json& t : g) {
            if (!t.is_string()) throw InputError("a forest is an array of S-expression strings");
            out.trees.push_back(t.get<std::string>());
        }
    } else if (g.is_array()) {
        for (const json& v : g) {
            if (!v.is_number()) throw InputError("a vector genotype is an array of numbers");
            out.vector.push_back(v.get<double>());
        }
    } else {
        throw InputError(std::string("a genotype is an array of numbers or S-expression strings, got ") + g.type_name());
    }
    return out;   // the session checks the form against the settings
}

json info_of(const run::EvaluationSession& session) {
    const io::Settings& s = session.settings();
    json j;
    j["cic"] = CIC_VERSION;
    j["protocol"] = kProtocol;
    j["settings"] = session.settings_file().string();
    j["experiment"] = s.experiment.type;
    j["form"] = session.form() == run::GenotypeForm::Vector ? "vector" : "forest";
    j["dimension"] = session.dimension();
    j["offset_count"] = session.offsets();
    j["vector_dimension"] = session.vector_dimension();
    j["descriptor"] = s.map_elites.enabled ? sim::to_string(s.map_elites.descriptor) : "none";
    j["workers"] = session.workers();
    return j;
}

int run_eval(const EvalOptions& o) {
    if (o.batch < 1) throw InputError("--batch must be at least 1, got " + std::to_string(o.batch));
    run::SessionOptions so;
    so.settings_file = o.settings;
    so.overrides = o.overrides;
    so.workers = o.workers;
    so.worker_executable = run::self_exec_path();
    so.warn = [](const std::string& line) { std::cerr << line << '\n'; };
    run::EvaluationSession session(so);
    if (o.info) {
        std::cout << info_of(session).dump() << std::endl;
        return 0;
    }
    LineReader reader;
    std::vector<std::string> lines;
    while (reader.next_batch(lines, static_cast<std::size_t>(o.batch))) {
        // Each line is parsed and checked alone: a bad line gets its error, the others their scores.
        std::vector<json> replies(lines.size());
        std::vector<run::Genotype> batch;
        std::vector<std::size_t> slot;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (lines[i].find_first_not_of(" \t\r") == std::string::npos) {
                replies[i] = nullptr;   // a blank line: skipped, no reply
                continue;
            }
            json& reply = replies[i] = json::object();
            try {
                const json line = json::parse(lines[i]);
                if (line.is_object() && line.contains("id")) reply["id"] = line["id"];
                run::Genotype g = genotype_of(line);
                session.check(g);
                batch.push_back(std::move(g));
                slot.push_back(i);
            } catch (const json::exception& e) {
                reply["error"] = std::string("not a JSON genotype: ") + e.what();
            } catch (const InputError& e) {
                reply["error"] = e.what();
            }
        }
        if (!batch.empty()) {
            const run::Scores s = session.evaluate(batch);
            for (std::size_t k = 0; k < slot.size(); ++k) {
                json& reply = replies[slot[k]];
                reply["fitness"] = s.fitness[k];
                reply["distance"] = s.distance[k];
                reply["elevation"] = s.elevation[k];
                reply["failed"] = s.failed[k] != 0;
                if (!s.descriptor[k].empty()) reply["descriptor"] = s.descriptor[k];
                if (s.failed[k]) reply["failure"] = s.failure[k];
            }
        }
        for (const json& r : replies)
            if (!r.is_null()) std::cout << r.dump() << '\n';
        std::cout.flush();
    }
    return 0;
}

} // namespace

void add_eval_command(Command& app, CommandContext& ctx) {
    auto o = std::make_shared<EvalOptions>();
    Command cmd = app.subcommand("eval", "Score genotypes given as JSON lines on stdin (a stream for any language)");
    cmd.option("--settings", o->settings, "Settings file of the experiment to score for (found like cic --settings)")
        .required();
    cmd.option("--set", o->overrides, "Override Section.key=value (repeatable), checked like cic --set");
    cmd.option("--workers", o->workers, "Worker processes").show_default();
    cmd.option("--batch", o->batch, "Most lines evaluated together (lines already waiting are batched)").show_default();
    cmd.flag("--info", o->info, "Print one JSON line describing the genotypes these settings take, and exit");
    cmd.on_run([o, &ctx] { ctx.exit_code = run_eval(*o); });
}

} // namespace cic::cli
