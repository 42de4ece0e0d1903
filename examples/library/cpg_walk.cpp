// One HyperGP-CPG evaluation through cic's library: a CPPF tree (the first
// argument, an S-expression over x0..x3) gives the weights of a CPG that
// drives robot R1 (4 legs) for the thesis's 15 s; prints the fitness (eq. 7.1).
// The same code runs in cic's worker processes, so the number equals what a
// cic run scores for this genotype.
#include <cstdio>
#include <exception>

#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/settings.hpp"
#include "cic/tree/tree.hpp"

int main(int argc, char** argv) {
    try {
        cic::io::Settings settings;   // every default: HyperGP on R1
        settings.neural.substrate = "cpg";
        const cic::hypergp::Model model = cic::hypergp::Model::from_settings(settings);
        const cic::tree::Forest genotype{cic::tree::Tree::parse(argc > 1 ? argv[1] : "(sin (sub x0 x2))")};
        const cic::hypergp::Outcome outcome = cic::hypergp::run(model, genotype);
        std::printf("%.17g\n", outcome.fitness);
        return outcome.failed ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cpg-walk: %s\n", e.what());
        return 2;
    }
}
