// Rigid Spheres: an interactive demo of the lecture "Rigid spheres".
#include "app/command_line.h"

int main(int argc, char** argv) { return app::runCommandLine(argc, argv); }
