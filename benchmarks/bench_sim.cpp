// Simulator speed: real-time factor, cost over a bare ODE loop, evaluations
// per second in worker processes, peak memory per worker.
// Run through scripts/bench-sim.sh, which prints the summary and the goals.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <ode/ode.h>
#include <sys/resource.h>
#include <unistd.h>

#include "cic/run/worker_jobs.hpp"
#include "cic/core/process_pool.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/sim/layout.hpp"

using namespace cic::sim;

namespace {

// The tripod gait that walks R1 with 6 legs forward (sim::tripod_gait).
std::vector<SineJoint> r1_gait() { return tripod_gait(6, 3); }

SimConfig thesis_config(double step, bool self_collision = true) {
    SimConfig c;   // 15 s, delayed start 2 s
    c.sample_step = step;
    c.self_collision = self_collision;
    return c;
}

// Args: control step in 0.1 ms, self-collision 0|1.
void BM_R1Sine(benchmark::State& state) {
    const RobotSpec robot = preset(1, true);
    const SimConfig cfg = thesis_config(state.range(0) / 10000.0, state.range(1) != 0);
    double simulated = 0;
    long steps = 0;
    for (auto _ : state) {
        SineController c(r1_gait());
        const EvalResult r = evaluate(robot, c, cfg);
        simulated += r.simulated_seconds;
        steps += r.steps;
        benchmark::DoNotOptimize(r.fitness);
    }
    state.counters["realtime_x"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
    state.counters["us_per_step"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["us_per_step"] = state.counters["us_per_step"].value * 1e6;
}
BENCHMARK(BM_R1Sine)->Args({125, 1})->Args({125, 0})->Args({50, 1})->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The same bodies, geoms, hinges and contacts stepped by hand with raw ODE
// calls, with the same collision set-up (ground, then the robot against itself
// except hinged bodies): what the simulator costs on top of ODE itself.
struct Bare {
    dWorldID world;
    dGeomID ground;
    dJointGroupID contacts;
    dContact proto{};
};

void bare_near(void* data, dGeomID a, dGeomID b) {
    auto* w = static_cast<Bare*>(data);
    if (dAreConnectedExcluding(dGeomGetBody(a), dGeomGetBody(b), dJointTypeContact)) return;
    dContact c[4];
    const int n = dCollide(a, b, 4, &c[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
        dContact k = w->proto;
        k.geom = c[i].geom;
        dJointAttach(dJointCreateContact(w->world, w->contacts, &k), dGeomGetBody(a), dGeomGetBody(b));
    }
}

double bare_ode_run(const BodyLayout& L, const SimConfig& cfg, const std::vector<SineJoint>& gait) {
    dRandSetSeed(0);
    Bare w;
    w.world = dWorldCreate();
    dThreadingImplementationID threading = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(w.world, dThreadingImplementationGetFunctions(threading), threading);
    dWorldSetGravity(w.world, 0, 0, -cfg.gravity);
    dWorldSetERP(w.world, cfg.erp);
    dWorldSetCFM(w.world, cfg.cfm);
    dWorldSetQuickStepNumIterations(w.world, cfg.quickstep_iterations);
    dSpaceID space = dSimpleSpaceCreate(nullptr);
    w.ground = dCreatePlane(nullptr, 0, 0, 1, 0);
    w.contacts = dJointGroupCreate(0);
    w.proto.surface.mode = dContactApprox1 | dContactSoftCFM | dContactBounce;
    w.proto.surface.mu = dInfinity;
    w.proto.surface.soft_cfm = cfg.soft_cfm;
    w.proto.surface.bounce = cfg.bounce;
    w.proto.surface.bounce_vel = 0.1;
    std::vector<dBodyID> bodies;
    std::vector<dMass> mass(static_cast<std::size_t>(L.body_count));
    for (int b = 0; b < L.body_count; ++b) {
        bodies.push_back(dBodyCreate(w.world));
        dBodySetPosition(bodies.back(), L.body_com[b][0], L.body_com[b][1], L.body_com[b][2]);
        dMassSetZero(&mass[b]);
    }
    for (const LayoutGeom& g : L.geoms) {
        const Vec3& c = L.body_com[g.body];
        dMass m;
        dMassSetBoxTotal(&m, g.mass, g.size[0], g.size[1], g.size[2]);
        dMassTranslate(&m, g.centre[0] - c[0], g.centre[1] - c[1], g.centre[2] - c[2]);
        dMassAdd(&mass[g.body], &m);
        dGeomID geom = dCreateBox(space, g.size[0], g.size[1], g.size[2]);
        dGeomSetBody(geom, bodies[g.body]);
        dGeomSetOffsetPosition(geom, g.centre[0] - c[0], g.centre[1] - c[1], g.centre[2] - c[2]);
    }
    for (int b = 0; b < L.body_count; ++b) {
        dMassTranslate(&mass[b], -mass[b].c[0], -mass[b].c[1], -mass[b].c[2]);
        dBodySetMass(bodies[b], &mass[b]);
    }
    std::vector<dJointID> hinges;
    for (const LayoutJoint& lj : L.joints) {
        dJointID j = dJointCreateHinge(w.world, nullptr);
        dJointAttach(j, bodies[lj.chassis_body], bodies[lj.panel_body]);
        dJointSetHingeAnchor(j, lj.anchor[0], lj.anchor[1], lj.anchor[2]);
        const Vec3 a = axis_vector(lj.axis);
        dJointSetHingeAxis(j, a[0], a[1], a[2]);
        dJointSetHingeParam(j, dParamLoStop, -kHingeLimit);
        dJointSetHingeParam(j, dParamHiStop, kHingeLimit);
        dJointSetHingeParam(j, dParamFMax, cfg.max_motor_force);
        hinges.push_back(j);
    }
    const long n = std::lround((cfg.sample_to - cfg.sample_from) / cfg.sample_step);
    for (long k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * cfg.sample_step;
        for (std::size_t j = 0; j < hinges.size(); ++j) {
            const SineJoint& p = gait[j];
            const double want = p.amplitude * std::sin(2 * std::numbers::pi * p.frequency * t + p.phase);
            dJointSetHingeParam(hinges[j], dParamVel, cfg.joint_gain * (dJointGetHingeAngle(hinges[j]) - want));
        }
        dSpaceCollide2(reinterpret_cast<dGeomID>(space), w.ground, &w, &bare_near);
        dSpaceCollide(space, &w, &bare_near);
        dWorldQuickStep(w.world, cfg.sample_step);
        dJointGroupEmpty(w.contacts);
    }
    const double y = dBodyGetPosition(bodies[0])[1];
    dJointGroupDestroy(w.contacts);
    dSpaceDestroy(space);
    dGeomDestroy(w.ground);
    dWorldSetStepThreadingImplementation(w.world, nullptr, nullptr);
    dWorldDestroy(w.world);
    dThreadingFreeImplementation(threading);
    return y;
}

void BM_BareOdeLoop(benchmark::State& state) {
    dInitODE2(0);
    const SimConfig cfg = thesis_config(0.0125);
    const BodyLayout L = make_body_layout(preset(1, true));
    const auto gait = r1_gait();
    double simulated = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bare_ode_run(L, cfg, gait));
        simulated += cfg.sample_to - cfg.sample_from;
    }
    state.counters["realtime_x"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BareOdeLoop)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// 20 evaluations (R1 6 legs, random sine gaits, 15 s each) in N worker
// processes: this benchmark program re-executes itself as the worker.
void BM_WorkerPool(benchmark::State& state) {
    const RobotSpec robot = preset(1, true);
    const SimConfig cfg = thesis_config(0.0125);
    std::vector<std::string> jobs;
    for (int i = 0; i < 20; ++i) {
        auto g = r1_gait();
        for (auto& j : g) j.phase += 0.3 * i;
        jobs.push_back(make_sine_job(robot, cfg, g));
    }
    cic::PoolOptions o;
    o.workers = static_cast<int>(state.range(0));
    o.argv = {"/proc/self/exe", "worker"};
    double evals = 0;
    {
        cic::ProcessPool pool(o);
        pool.run({jobs[0]});   // warm up: workers started and loaded
        for (auto _ : state) {
            auto r = pool.run(jobs);
            evals += static_cast<double>(r.size());
            if (!r[0].ok) state.SkipWithError(r[0].error.c_str());
        }
    }
    state.counters["evals_per_s"] = benchmark::Counter(evals, benchmark::Counter::kIsRate);
    rusage ru{};
    getrusage(RUSAGE_CHILDREN, &ru);   // the largest worker reaped so far
    state.counters["worker_maxrss_MB"] = static_cast<double>(ru.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_WorkerPool)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "worker") == 0) {
        const int out = ::dup(1);
        ::dup2(2, 1);
        const auto kinds = cic::run::make_worker_job_kinds({});
        return cic::serve_worker(0, out, [&](const std::string& job) { return cic::run::dispatch_worker_job(kinds, job); });
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
