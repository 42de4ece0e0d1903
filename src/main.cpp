#include "cic/cli/cli.hpp"

int main(int argc, char** argv) { return cic::app::main(argc, argv); }
