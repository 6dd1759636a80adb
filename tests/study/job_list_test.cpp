// The emitted job lists: the Slurm script is valid bash and names every run; each GNU parallel
// line starts a run that is not there and continues one that is.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/job_list.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

const StudyLayout kLayout{"/data/my study", "/opt/grainlab/bin/grainlab"};

TEST(JobList, SlurmScriptIsValidBashWithOneArrayTaskPerRun) {
    const std::vector<std::string> runs{"ref-seed1", "ref-seed2", "damping-none-seed1"};
    const std::string script = slurmScript(kLayout, "damping", runs, 2);
    EXPECT_NE(script.find("#SBATCH --array=0-2\n"), std::string::npos);
    EXPECT_NE(script.find("#SBATCH --cpus-per-task=2\n"), std::string::npos);
    for (const auto& r : runs) {
        EXPECT_NE(script.find("  '" + r + "'\n"), std::string::npos) << r;
    }
    const fs::path file = fs::temp_directory_path() / "grainlab-study.slurm";
    std::ofstream(file) << script;
    EXPECT_EQ(std::system(("bash -n '" + file.string() + "'").c_str()), 0);
}

TEST(JobList, ParallelLinesStartOrContinueARunAndQuoteThePaths) {
    const std::string list = parallelJobList(kLayout, {"ref-seed1", "a-seed2"});
    EXPECT_EQ(list, "if [ -e '/data/my study/runs/ref-seed1/run.h5' ]; then "
                    "'/opt/grainlab/bin/grainlab' 'run' '--resume' '/data/my study/runs/ref-seed1' "
                    "'--quiet'; else '/opt/grainlab/bin/grainlab' 'run' "
                    "'/data/my study/experiments/ref-seed1.json' '--out' "
                    "'/data/my study/runs/ref-seed1' '--quiet'; fi\n"
                    "if [ -e '/data/my study/runs/a-seed2/run.h5' ]; then "
                    "'/opt/grainlab/bin/grainlab' 'run' '--resume' '/data/my study/runs/a-seed2' "
                    "'--quiet'; else '/opt/grainlab/bin/grainlab' 'run' "
                    "'/data/my study/experiments/a-seed2.json' '--out' "
                    "'/data/my study/runs/a-seed2' '--quiet'; fi\n");
}

TEST(JobList, ShellQuoteSurvivesQuotes) {
    EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
    const fs::path file = fs::temp_directory_path() / "grainlab-quote.sh";
    std::ofstream(file) << "[ " << shellQuote("a 'b' $c") << " = \"a 'b' \\$c\" ]\n";
    EXPECT_EQ(std::system(("sh '" + file.string() + "'").c_str()), 0);
}

} // namespace
} // namespace grainlab
