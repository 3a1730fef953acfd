// libFuzzer target: the `stepwise` command line's parsers (src/app/options.cpp), every command's.
//
// The input is a command line: its arguments separated by NUL bytes, the first one the command.
// What counts as a bug is checkCommandLine() in fuzz_oracles.hpp: anything but a UsageError out
// of a parser, and any crash or undefined operation. Nothing is run: only parsed.
//   build/fuzz/tests/fuzz/fuzz_command_line -max_total_time=600 build/fuzz/corpus/cli tests/fuzz/seeds/cli
// An input it stops on goes into tests/fuzz/regressions/cli/ once fixed.
#include <cstdio>
#include <cstdlib>

#include "fuzz_oracles.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace stepwise::fuzz;
    try {
        checkCommandLine(commandLineOf(std::string_view(reinterpret_cast<const char*>(data), size)));
    } catch (const FuzzFailure& failure) {
        std::fprintf(stderr, "fuzz_command_line: %s\n", failure.what());
        std::abort();
    }
    return 0;
}
