// The grainlab executable: see app/command_line.h.
#include "command_line.h"

int main(int argc, char** argv) {
    return grainlab::runCommandLine(argc, argv);
}
