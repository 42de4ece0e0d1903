// cic._core: the thin skin between Python and the run layer's EvaluationSession
// (cic/run/evaluation_session.hpp). It converts, never computes: every number
// comes from the same library code and worker processes as a run's. The
// friendly API (cic.Evaluator, cic.simulate, cic.read_run) is python/cic/*.py.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/run/evaluation_session.hpp"
#include "cic/run/settings_lookup.hpp"
#include "cic/sim/evaluate.hpp"

namespace py = pybind11;
using namespace cic;
using run::EvaluationSession;
using run::Genotype;
using run::GenotypeForm;

namespace {

py::array_t<double> vector_array(const std::vector<double>& v) {
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

// rows x cols, row-major, from a flat vector.
template <class T>
py::array_t<T> matrix_array(const std::vector<T>& flat, std::size_t rows, std::size_t cols) {
    py::array_t<T> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
    if (rows * cols != flat.size()) throw std::logic_error("cic._core: matrix size mismatch");
    std::copy(flat.begin(), flat.end(), a.mutable_data());
    return a;
}

// One row per genotype; a failed evaluation carries no descriptor: a row of NaN.
// None when no genotype has one (the settings ask for none).
py::object descriptor_matrix(const std::vector<std::vector<double>>& rows) {
    std::size_t width = 0;
    for (const auto& row : rows) width = std::max(width, row.size());
    if (width == 0) return py::none();
    std::vector<double> flat(rows.size() * width, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < rows.size(); ++i)
        std::copy(rows[i].begin(), rows[i].end(), flat.begin() + static_cast<std::ptrdiff_t>(i * width));
    return matrix_array(flat, rows.size(), width);
}

const char* form_name(GenotypeForm f) { return f == GenotypeForm::Vector ? "vector" : "forest"; }

// One session, shared by the Python threads that use it: calls are serialised.
// The lock is taken after the GIL is released, so a thread waiting for it
// never holds the GIL that the running batch's Ctrl-C check needs.
class Session {
public:
    Session(const std::string& settings, int workers, const std::vector<std::string>& overrides,
            const std::string& worker_executable) {
        run::SessionOptions o;
        o.settings_file = settings;
        o.overrides = overrides;
        o.workers = workers;
        o.worker_executable = worker_executable;
        // Checked every 50 ms during a batch: Python's own signal handlers run
        // here (main thread), so Ctrl-C raises KeyboardInterrupt after the
        // workers are ended.
        o.interrupted = [this] {
            py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() == 0) return false;
            pending_ = std::make_unique<py::error_already_set>();
            return true;
        };
        o.warn = [this](const std::string& line) { warnings_.push_back(line); };
        o.note = [this](const std::string& line) { notes_.push_back(line); };   // Python's warnings say them
        session_ = std::make_unique<EvaluationSession>(std::move(o));
    }

    std::string form() const { return form_name(session_->form()); }
    std::size_t dimension() const { return session_->dimension(); }
    std::size_t offset_count() const { return session_->offsets(); }
    std::size_t vector_dimension() const { return session_->vector_dimension(); }
    int workers() const { return session_->workers(); }
    std::string settings_file() const { return session_->settings_file().string(); }
    std::string experiment() const { return session_->settings().experiment.type; }
    std::string descriptor() const {
        const auto& s = session_->settings();
        return s.map_elites.enabled ? sim::to_string(s.map_elites.descriptor) : "none";
    }
    std::vector<std::string> take_warnings() { return std::exchange(warnings_, {}); }
    std::vector<std::string> take_notes() { return std::exchange(notes_, {}); }

    py::array_t<double> in_box(const std::vector<double>& x, const std::string& reading) const {
        run::BoxReading r = run::BoxReading::Settings;
        if (reading == "reflect") r = run::BoxReading::Reflect;
        else if (reading == "clip") r = run::BoxReading::Clip;
        else if (reading != "settings") throw InputError("in_box: reading is settings, reflect or clip, got " + reading);
        return vector_array(session_->in_box(x, r));
    }

    py::dict decode(const std::vector<double>& x) const {
        const sim::GaitSpec g = session_->decode(x);
        std::vector<double> amplitude, phase, offset, amplitude2, phase2;
        for (const sim::GaitJoint& j : g.joints) {
            amplitude.push_back(j.amplitude);
            phase.push_back(j.phase);
            offset.push_back(j.offset);
            amplitude2.push_back(j.amplitude2);
            phase2.push_back(j.phase2);
        }
        py::dict d;
        d["frequency"] = g.frequency;
        d["joint_names"] = session_->joint_names();
        d["amplitude"] = vector_array(amplitude);
        d["phase"] = vector_array(phase);
        d["offset"] = vector_array(offset);
        d["amplitude2"] = vector_array(amplitude2);
        d["phase2"] = vector_array(phase2);
        d["second_harmonic"] = session_->settings().gait.second_harmonic;
        return d;
    }

    py::dict evaluate_vectors(py::array_t<double, py::array::c_style> xs) {
        if (xs.ndim() != 2) throw InputError("a batch of vectors is a 2-D array (one row per genotype)");
        std::vector<Genotype> batch(static_cast<std::size_t>(xs.shape(0)));
        const auto cols = static_cast<std::size_t>(xs.shape(1));
        const double* data = xs.data();
        for (std::size_t i = 0; i < batch.size(); ++i) batch[i].vector.assign(data + i * cols, data + (i + 1) * cols);
        return run(batch);
    }

    // `offsets`: one row per forest (Offset-HybrID), or none at all.
    py::dict evaluate_forests(const std::vector<std::vector<std::string>>& forests,
                              const std::vector<std::vector<double>>& offsets) {
        if (!offsets.empty() && offsets.size() != forests.size())
            throw InputError("offsets: one row per genotype of the batch");
        std::vector<Genotype> batch(forests.size());
        for (std::size_t i = 0; i < forests.size(); ++i) {
            batch[i].trees = forests[i];
            if (!offsets.empty()) batch[i].offsets = offsets[i];
        }
        return run(batch);
    }

    py::dict simulate(const std::vector<double>& vector, const std::vector<std::string>& trees, bool trace,
                      const std::vector<double>& offsets) {
        Genotype g{vector, trees, offsets};
        run::Walk w;
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            w = session_->simulate(g, trace);
        }
        const std::size_t steps = w.time.size(), joints = w.joint_names.size(), feet = w.foot_names.size();
        py::dict d;
        d["fitness"] = w.fitness;
        d["distance"] = w.distance;
        d["elevation"] = w.elevation;
        d["failed"] = w.failed;
        d["failure"] = w.failure;
        d["joint_names"] = w.joint_names;
        d["foot_names"] = w.foot_names;
        d["time"] = vector_array(w.time);
        d["centre"] = matrix_array(w.centre, steps, 3);
        d["angles"] = matrix_array(w.angles, steps, joints);
        d["targets"] = matrix_array(w.targets, steps, joints);
        d["feet"] = matrix_array(std::vector<unsigned char>(w.feet.begin(), w.feet.end()), steps, feet);
        d["duty_factors"] = vector_array(w.duty_factors);
        return d;
    }

    void close() {
        py::gil_scoped_release release;
        std::lock_guard lock(mutex_);
        session_->close();
    }

private:
    py::dict run(const std::vector<Genotype>& batch) {
        run::Scores s;
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            try {
                s = session_->evaluate(batch);
            } catch (const Interrupted&) {
                py::gil_scoped_acquire gil;
                if (pending_) {
                    auto e = std::move(pending_);
                    e->restore();
                    throw py::error_already_set();
                }
                throw;
            }
        }
        py::dict d;
        d["fitness"] = vector_array(s.fitness);
        d["distance"] = vector_array(s.distance);
        d["elevation"] = vector_array(s.elevation);
        py::array_t<bool> failed(static_cast<py::ssize_t>(s.failed.size()));
        for (std::size_t i = 0; i < s.failed.size(); ++i) failed.mutable_data()[i] = s.failed[i] != 0;
        d["failed"] = failed;
        d["failure"] = s.failure;
        if (py::object desc = descriptor_matrix(s.descriptor); !desc.is_none()) d["descriptor"] = desc;
        return d;
    }

    std::mutex mutex_;
    std::unique_ptr<EvaluationSession> session_;
    std::unique_ptr<py::error_already_set> pending_;   // the exception Ctrl-C raised mid-batch
    std::vector<std::string> warnings_;
    std::vector<std::string> notes_;   // e.g. which installed settings file a bare name found
};

py::dict read_run_best(const std::string& folder) {
    const run::RunBest b = run::read_run_best(folder);
    py::dict d;
    d["form"] = form_name(b.form);
    d["vector"] = vector_array(b.genotype.vector);
    d["trees"] = b.genotype.trees;
    d["offsets"] = vector_array(b.genotype.offsets);
    d["fitness"] = b.fitness;
    d["generation"] = b.generation;
    d["settings"] = b.settings.string();
    return d;
}

} // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "cic's evaluation core (use the cic package, not this module)";
    m.attr("__version__") = CIC_VERSION;
    // cic's bad input (a settings key, a genotype) is a ValueError with cic's own one-line message;
    // a settings file found nowhere is Python's FileNotFoundError.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const run::SettingsNotFound& e) {
            PyErr_SetString(PyExc_FileNotFoundError, e.what());
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const Interrupted&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        }
    });
    py::class_<Session>(m, "Session")
        .def(py::init<const std::string&, int, const std::vector<std::string>&, const std::string&>(),
             py::arg("settings"), py::arg("workers"), py::arg("overrides"), py::arg("worker_executable"))
        .def_property_readonly("form", &Session::form)
        .def_property_readonly("dimension", &Session::dimension)
        .def_property_readonly("offset_count", &Session::offset_count)
        .def_property_readonly("vector_dimension", &Session::vector_dimension)
        .def_property_readonly("workers", &Session::workers)
        .def_property_readonly("settings_file", &Session::settings_file)
        .def_property_readonly("experiment", &Session::experiment)
        .def_property_readonly("descriptor", &Session::descriptor)
        .def("take_warnings", &Session::take_warnings)
        .def("take_notes", &Session::take_notes)
        .def("in_box", &Session::in_box, py::arg("x"), py::arg("reading"))
        .def("decode", &Session::decode, py::arg("x"))
        .def("evaluate_vectors", &Session::evaluate_vectors)
        .def("evaluate_forests", &Session::evaluate_forests, py::arg("forests"), py::arg("offsets"))
        .def("simulate", &Session::simulate, py::arg("vector"), py::arg("trees"), py::arg("trace"), py::arg("offsets"))
        .def("close", &Session::close);
    m.def("read_run_best", &read_run_best, py::arg("folder"));
}
