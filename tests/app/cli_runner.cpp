#include "cli_runner.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>

#include "support/test_paths.h"

namespace pt::test {

CliResult runCli(const std::string& args) {
    static int counter = 0;
    const std::string base = tempDir() + "/cli" + std::to_string(counter++);
    const std::string command =
        std::string("'") + PT_RENDER_CLI + "' " + args + " >'" + base + ".out' 2>'" + base + ".err'";
    const int status = std::system(command.c_str());
    CliResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readTextFile(base + ".out");
    r.err = readTextFile(base + ".err");
    return r;
}

}  // namespace pt::test
