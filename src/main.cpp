#include "cic/cli/cli.hpp"

int main(int argc, char** argv) { return cic::cli::main(argc, argv); }
