#include "cli/farm.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/process.hpp"
#include "cli/render_options.hpp"
#include "core/atomic_file.hpp"
#include "core/preset.hpp"

namespace fraktal::cli {

using nlohmann::json;

// How jobs.json records the plan.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SlurmOptions, partition, account, time, cpusPerTask, extra)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FarmPlan, preset, output, frames, chunk, tiles, size, spp, fraktal, slurm)

int chunkCount(const FrameRange& range, int chunk) {
    const int frames = int(range.frames().size());
    return (frames + chunk - 1) / chunk;
}

std::vector<int> chunkFrames(const FrameRange& range, int chunk, int index) {
    const std::vector<int> all = range.frames();
    const size_t begin = size_t(index) * size_t(chunk);
    if (index < 0 || begin >= all.size()) return {};
    return std::vector<int>(all.begin() + long(begin), all.begin() + long(std::min(all.size(), begin + size_t(chunk))));
}

std::string arrayIndexList(const std::vector<int>& sorted) {
    std::string out;
    for (size_t i = 0; i < sorted.size();) {
        size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
        out += (out.empty() ? "" : ",") + std::to_string(sorted[i]);
        if (j > i) out += "-" + std::to_string(sorted[j]);
        i = j + 1;
    }
    return out;
}

std::string shellQuote(const std::string& word) {
    const bool safe = !word.empty() && word.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789_-+=/.,:%@#") == std::string::npos;
    if (safe) return word;
    std::string q = "'";
    for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::filesystem::path farmDirOf(const FarmPlan& plan) {
    return std::filesystem::path(plan.output).parent_path() / ".farm";
}

std::filesystem::path tilePartPath(const FarmPlan& plan, int part) {
    return farmDirOf(plan) / "parts" /
           (std::filesystem::path(plan.output).stem().string() + ".part-" + std::to_string(part) + "-of-" +
            std::to_string(plan.tiles) + ".exr");
}

namespace {

std::string renderOverrides(const FarmPlan& plan) {
    std::string s = " --threads \"${SLURM_CPUS_PER_TASK:-1}\"";
    if (!plan.size.empty()) s += " --size " + shellQuote(plan.size);
    if (plan.spp) s += " --spp " + std::to_string(plan.spp);
    return s;
}

std::string scriptHeader(const std::string& what) {
    return "#!/bin/bash\n# Written by `fraktal farm submit`: " + what +
           "\n# Submitted with sbatch (options on its command line, recorded in jobs.json beside this file).\n"
           "set -euo pipefail\n";
}

}  // namespace

std::string frameArrayScript(const FarmPlan& plan) {
    const FrameRange r = parseFrameRange(plan.frames);
    std::ostringstream s;
    s << scriptHeader("array task i renders chunk i (" + std::to_string(plan.chunk) + " frames) of frames " +
                      plan.frames + " of " + plan.preset +
                      ".\n# `fraktal render --frames` skips frames already complete: a task run again redoes only "
                      "what is missing.");
    s << "first=$(( " << r.first << " + SLURM_ARRAY_TASK_ID * " << plan.chunk * r.step << " ))\n";
    s << "last=$(( first + " << (plan.chunk - 1) * r.step << " ))\n";
    s << "if (( last > " << r.last << " )); then last=" << r.last << "; fi\n";
    s << "exec " << shellQuote(plan.fraktal) << " render " << shellQuote(plan.preset)
      << " --frames \"${first}-${last}:" << r.step << "\" -o " << shellQuote(plan.output) << renderOverrides(plan)
      << "\n";
    return s.str();
}

std::string tileArrayScript(const FarmPlan& plan) {
    std::ostringstream s;
    s << scriptHeader("array task i renders part i+1 of " + std::to_string(plan.tiles) + " of the still " +
                      plan.preset + ";\n# a merge job that depends on the array joins them into " + plan.output + ".");
    s << "part=$(( SLURM_ARRAY_TASK_ID + 1 ))\n";
    // tilePartPath's name, with the part number from the shell.
    const std::filesystem::path partStem =
        farmDirOf(plan) / "parts" / (std::filesystem::path(plan.output).stem().string() + ".part-");
    s << "exec " << shellQuote(plan.fraktal) << " render " << shellQuote(plan.preset) << " --tile \"${part}/"
      << plan.tiles << "\" -o " << shellQuote(partStem.string()) << "\"${part}\""
      << shellQuote("-of-" + std::to_string(plan.tiles) + ".exr") << renderOverrides(plan) << "\n";
    return s.str();
}

std::string mergeScript(const FarmPlan& plan) {
    std::ostringstream s;
    s << scriptHeader("joins the " + std::to_string(plan.tiles) + " parts of " + plan.preset + " into " + plan.output +
                      ".");
    s << "exec " << shellQuote(plan.fraktal) << " merge";
    for (int i = 1; i <= plan.tiles; ++i) s << " " << shellQuote(tilePartPath(plan, i).string());
    s << " -o " << shellQuote(plan.output) << "\n";
    return s.str();
}

namespace {

struct SubmitOptions {
    FarmPlan plan;  // as given on the command line; planOf makes the paths absolute and checks it
    bool dryRun = false;
};

FarmPlan planFromJson(const json& j, const std::string& file) {
    try {
        FarmPlan p = j.get<FarmPlan>();
        if (p.chunk < 1) throw std::runtime_error("chunk must be at least 1");
        return p;
    } catch (const std::exception& e) {
        throw std::runtime_error(file + ": plan: " + e.what());
    }
}

std::filesystem::path jobsFile(const std::filesystem::path& farmDir) { return farmDir / "jobs.json"; }

json readJobs(const std::filesystem::path& farmDir) {
    const auto path = jobsFile(farmDir);
    std::ifstream in(path);
    if (!in) return json{{"format", "fraktal-farm"}, {"version", 1}, {"jobs", json::array()}};
    try {
        json j = json::parse(in);
        if (j.value("format", "") != "fraktal-farm" || !j.contains("jobs") || !j["jobs"].is_array())
            throw std::runtime_error("not a fraktal farm record (format fraktal-farm with a jobs list)");
        return j;
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

// The preset every frame (or the still) is rendered with: the plan's size and spp applied.
Preset plannedPreset(const FarmPlan& plan) {
    Preset p = loadPreset(plan.preset);
    if (!plan.size.empty()) parseSize(plan.size, p.render);
    if (plan.spp) p.render.spp = plan.spp;
    return p;
}

struct WorkState {
    std::vector<int> done, missing, broken;  // frames (or parts, from 1)
    std::vector<std::string> brokenWhy;
    std::vector<int> tasksToRun;  // array indices whose frames (or part) are not all complete
    bool wholeStillComplete = false;
};

WorkState checkWork(const FarmPlan& plan) {
    WorkState w;
    const Preset preset = plannedPreset(plan);
    auto record = [&](int item, const std::filesystem::path& path, FrameFileState state, const std::string& why) {
        if (state == FrameFileState::Complete) {
            w.done.push_back(item);
            return true;
        }
        (state == FrameFileState::Missing ? w.missing : w.broken).push_back(item);
        if (state == FrameFileState::Broken) w.brokenWhy.push_back(path.string() + ": " + why);
        return false;
    };
    if (plan.isStill()) {
        w.wholeStillComplete = checkFrameFile(plan.output, preset) == FrameFileState::Complete;
        for (int i = 1; i <= plan.tiles; ++i) {
            std::string why;
            const auto path = tilePartPath(plan, i);
            if (!record(i, path, checkFrameFile(path, preset, &why, i - 1, plan.tiles), why) && !w.wholeStillComplete)
                w.tasksToRun.push_back(i - 1);
        }
        return w;
    }
    const FrameRange range = parseFrameRange(plan.frames);
    for (int t = 0; t < chunkCount(range, plan.chunk); ++t) {
        bool complete = true;
        for (int f : chunkFrames(range, plan.chunk, t)) {
            std::string why;
            const auto path = framePath(plan.output, f);
            complete &= record(f, path, checkFrameFile(path, sequenceFramePreset(preset, f), &why), why);
        }
        if (!complete) w.tasksToRun.push_back(t);
    }
    return w;
}

// "0-3, 7, 9-11" for sorted numbers.
std::string listOf(const std::vector<int>& sorted) {
    const std::string s = arrayIndexList(sorted);
    std::string spaced;
    for (char c : s) {
        spaced += c;
        if (c == ',') spaced += ' ';
    }
    return spaced;
}

// Each recorded job's tasks as squeue sees them ("" when the job has left the queue); nullopt when
// squeue is not available.
struct QueueState {
    bool available = true;
    std::string note;
    std::vector<std::pair<std::string, std::string>> tasks;  // job id, "TASK STATE" lines
};

QueueState queueState(const json& jobs) {
    QueueState q;
    for (const json& job : jobs["jobs"]) {
        const std::string id = job.value("id", "");
        if (id.empty()) continue;
        ProgramResult r;
        try {
            r = runProgram({"squeue", "--noheader", "--array", "--format=%i %T %R", "--jobs=" + id});
        } catch (const ProgramNotStarted& e) {
            q.available = false;
            q.note = e.what();
            return q;
        }
        if (r.exitCode != 0) {
            q.tasks.emplace_back(id, r.err.find("Invalid job id") != std::string::npos
                                         ? ""
                                         : "squeue failed (" + r.describeStatus() + "): " + tailOf(r.err, 300));
            continue;
        }
        q.tasks.emplace_back(id, tailOf(r.out, 100000));
    }
    return q;
}

std::string sbatchFailure(const std::string& what, const ProgramResult& r) {
    return "sbatch failed (" + r.describeStatus() + ") submitting " + what + ": " +
           (tailOf(r.err).empty() ? "(no error output)" : tailOf(r.err)) + "; nothing submitted";
}

std::vector<std::string> sbatchCommand(const FarmPlan& plan, const std::string& jobName,
                                       const std::filesystem::path& logs) {
    std::vector<std::string> a = {"sbatch", "--parsable", "--job-name=" + jobName,
                                  "--cpus-per-task=" + std::to_string(plan.slurm.cpusPerTask)};
    if (!plan.slurm.partition.empty()) a.push_back("--partition=" + plan.slurm.partition);
    if (!plan.slurm.account.empty()) a.push_back("--account=" + plan.slurm.account);
    if (!plan.slurm.time.empty()) a.push_back("--time=" + plan.slurm.time);
    a.push_back("--output=" + logs.string());
    a.insert(a.end(), plan.slurm.extra.begin(), plan.slurm.extra.end());
    return a;
}

std::string commandLine(const std::vector<std::string>& argv) {
    std::string s;
    for (const std::string& a : argv) {
        if (!s.empty()) s += ' ';
        s += shellQuote(a);
    }
    return s;
}

std::string utcNow() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return buf;
}

// Submits `script` (already written) with `argv`; returns the job id sbatch printed.
std::string submit(std::vector<std::string> argv, const std::filesystem::path& script, const std::string& what) {
    argv.push_back(script.string());
    ProgramResult r;
    try {
        r = runProgram(argv);
    } catch (const ProgramNotStarted& e) {
        throw std::runtime_error(std::string(e.what()) +
                                 "; `fraktal farm submit` needs Slurm's sbatch on this "
                                 "machine (use --dry-run to only write the script)");
    }
    if (r.exitCode != 0) throw std::runtime_error(sbatchFailure(what, r));
    // --parsable prints "jobid" or "jobid;cluster".
    std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error("sbatch printed no job id for " + what + " (output: '" + tailOf(r.out, 200) + "')");
    return id;
}

FarmPlan planOf(const FarmPlan& given) {
    namespace fs = std::filesystem;
    FarmPlan p = given;
    std::error_code ec;
    if (!fs::is_regular_file(p.preset, ec)) throw std::runtime_error(p.preset + ": no such preset file");
    p.preset = fs::absolute(p.preset).lexically_normal().string();
    p.output = fs::absolute(p.output).lexically_normal().string();
    if (p.fraktal.empty())
        p.fraktal = fs::read_symlink("/proc/self/exe", ec).string();
    else if (p.fraktal.find('/') != std::string::npos)
        p.fraktal = fs::absolute(p.fraktal).lexically_normal().string();
    if (p.fraktal.empty()) throw std::runtime_error("cannot tell where the fraktal program is; pass --fraktal PATH");
    for (const std::string& a : p.slurm.extra)
        if (a.find('\n') != std::string::npos) throw std::runtime_error("--sbatch-arg: a line break in '" + a + "'");
    if (p.frames.empty() == (p.tiles == 0))
        throw std::runtime_error("farm submit: give --frames FIRST-LAST (an animation) or --tiles N (a still)");
    const Preset preset = plannedPreset(p);  // bad preset, size: fails here, before anything is written
    if (p.isStill()) {
        if (p.tiles > preset.render.height)
            throw std::runtime_error("--tiles " + std::to_string(p.tiles) + ": more parts than the image's " +
                                     std::to_string(preset.render.height) + " rows");
        AtomicFile checkFolder(p.output);
        if (!p.output.ends_with(".exr")) throw std::runtime_error(p.output + ": the still's output must be an .exr");
    } else {
        checkFrameRangeWithin(parseFrameRange(p.frames), preset.animation, p.preset);
        checkFramePattern(p.output);
    }
    return p;
}

int runSubmit(const SubmitOptions& o) {
    namespace fs = std::filesystem;
    const FarmPlan plan = planOf(o.plan);
    const fs::path farmDir = farmDirOf(plan);
    json jobs = readJobs(farmDir);

    const WorkState work = checkWork(plan);
    const bool mergeNeeded = plan.isStill() && !work.wholeStillComplete;
    if (work.tasksToRun.empty() && !mergeNeeded) {
        std::printf("nothing to submit: every %s of %s is complete\n", plan.isStill() ? "part" : "frame",
                    plan.output.c_str());
        return 0;
    }
    // Tasks of an earlier submission still queued or running would render the same frames twice.
    if (!o.dryRun) {
        const QueueState q = queueState(jobs);
        for (const auto& [id, tasks] : q.tasks)
            if (!tasks.empty() && tasks.find("squeue failed") == std::string::npos)
                throw std::runtime_error("job " + id + " of an earlier submission is still in the queue:\n" + tasks +
                                         "\nwait for it (fraktal farm status " +
                                         fs::path(plan.output).parent_path().string() +
                                         ") or scancel it, then submit again");
    }

    std::error_code ec;
    fs::create_directories(farmDir / "logs", ec);
    if (plan.isStill()) fs::create_directories(farmDir / "parts", ec);
    if (ec) throw std::runtime_error(farmDir.string() + ": cannot create the farm folder: " + ec.message());

    const std::string stem = fs::path(plan.preset).stem().string();  // the jobs' names in squeue
    const std::string array = arrayIndexList(work.tasksToRun);
    struct Submission {
        std::string kind, script, array;
        std::vector<std::string> argv;
    };
    std::vector<Submission> subs;
    if (!work.tasksToRun.empty()) {
        Submission s{plan.isStill() ? "tiles" : "frames",
                     plan.isStill() ? tileArrayScript(plan) : frameArrayScript(plan), array,
                     sbatchCommand(plan, "fraktal-" + stem, farmDir / "logs" / "%A_%a.log")};
        s.argv.push_back("--array=" + array);
        subs.push_back(std::move(s));
    }
    if (mergeNeeded)
        subs.push_back({"merge", mergeScript(plan), "",
                        sbatchCommand(plan, "fraktal-merge-" + stem, farmDir / "logs" / "%j.log")});

    const std::string tag = std::to_string(jobs["jobs"].size() + 1);
    std::string arrayId;
    for (Submission& s : subs) {
        const fs::path script = farmDir / (s.kind + "-" + tag + ".sbatch");
        if (s.kind == "merge" && !arrayId.empty()) {
            s.argv.push_back("--dependency=afterok:" + arrayId);
            s.argv.push_back("--kill-on-invalid-dep=yes");
        }
        writeFileAtomically(script, s.script + "# " + commandLine(s.argv) + " " + shellQuote(script.string()) + "\n");
        fs::permissions(script, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add, ec);
        if (o.dryRun) {
            std::printf("== %s (not submitted: --dry-run)\n%s# %s %s\n", script.c_str(), s.script.c_str(),
                        commandLine(s.argv).c_str(), shellQuote(script.string()).c_str());
            continue;
        }
        const std::string what =
            s.kind == "merge" ? "the merge job" : "array " + s.array + " (" + script.string() + ")";
        const std::string id = submit(s.argv, script, what);
        if (s.kind != "merge") arrayId = id;
        jobs["jobs"].push_back(
            {{"id", id}, {"kind", s.kind}, {"array", s.array}, {"script", script.string()}, {"submitted", utcNow()}});
        jobs["plan"] = plan;
        // Recorded after every submission, so a failure of the next one loses no job id.
        writeFileAtomically(jobsFile(farmDir), jobs.dump(2) + "\n");
        std::printf("submitted job %s: %s%s\n", id.c_str(), s.kind.c_str(),
                    s.array.empty() ? (arrayId.empty() ? "" : (" after job " + arrayId).c_str())
                                    : (" array " + s.array).c_str());
    }
    return 0;
}

int runStatus(const std::string& dir) {
    namespace fs = std::filesystem;
    const fs::path farmDir = fs::path(dir) / ".farm";
    std::error_code ec;
    if (!fs::is_regular_file(jobsFile(farmDir), ec))
        throw std::runtime_error(dir + ": no farm here (" + jobsFile(farmDir).string() +
                                 " is missing; `fraktal farm submit` writes it)");
    const json jobs = readJobs(farmDir);
    if (!jobs.contains("plan")) throw std::runtime_error(jobsFile(farmDir).string() + ": no plan recorded");
    const FarmPlan plan = planFromJson(jobs["plan"], jobsFile(farmDir).string());
    const WorkState w = checkWork(plan);
    const char* item = plan.isStill() ? "parts" : "frames";
    if (plan.isStill())
        std::printf("still %s in %d parts: %s\n", plan.output.c_str(), plan.tiles,
                    w.wholeStillComplete ? "merged, complete" : "not merged yet");
    else
        std::printf("frames %s of %s into %s\n", plan.frames.c_str(), plan.preset.c_str(), plan.output.c_str());
    std::printf("done: %zu %s\n", w.done.size(), item);
    std::printf("missing: %zu%s%s\n", w.missing.size(), w.missing.empty() ? "" : " ", listOf(w.missing).c_str());
    std::printf("broken: %zu%s%s\n", w.broken.size(), w.broken.empty() ? "" : " ", listOf(w.broken).c_str());
    for (const std::string& why : w.brokenWhy) std::printf("  %s\n", why.c_str());
    const QueueState q = queueState(jobs);
    if (!q.available) {
        std::printf("queue: unknown (%s)\n", q.note.c_str());
        return 0;
    }
    for (const auto& [id, tasks] : q.tasks) {
        std::string kind;
        for (const json& job : jobs["jobs"])
            if (job.value("id", "") == id) kind = job.value("kind", "") + " " + job.value("array", "");
        std::printf("job %s (%s): %s\n", id.c_str(), kind.c_str(), tasks.empty() ? "not in the queue (finished)" : "");
        if (!tasks.empty()) std::printf("%s\n", tasks.c_str());
    }
    return 0;
}

}  // namespace

void addFarmCommand(CLI::App& app, Action& action) {
    CLI::App* farm = app.add_subcommand("farm", "Render an animation or a big still on a Slurm cluster (job arrays)");
    farm->require_subcommand(1);
    auto o = std::make_shared<SubmitOptions>();
    CLI::App* sub = farm->add_subcommand(
        "submit",
        "Write an sbatch job-array script into the output's .farm/ folder and submit it; run again to "
        "resubmit only what is missing or broken");
    sub->add_option("preset", o->plan.preset, "Preset (an animated one with --frames, any with --tiles)")->required();
    sub->add_option("-o,--output", o->plan.output,
                    "Frame pattern (shared folder visible to every node), e.g. /shared/out/frame_####.exr; with "
                    "--tiles, the still's EXR")
        ->required();
    sub->add_option("--frames", o->plan.frames, "Frames FIRST-LAST[:STEP] of the animation");
    sub->add_option("--chunk", o->plan.chunk, "Frames per array task (default 8)")->check(CLI::Range(1, 100000));
    sub->add_option("--tiles", o->plan.tiles, "A still: one array task per part, then a merge job")
        ->check(CLI::Range(1, 100000));
    sub->add_option("--size", o->plan.size, "Image size WIDTHxHEIGHT (default: the preset's)");
    sub->add_option("--spp", o->plan.spp, "Samples per pixel (default: the preset's)")->check(CLI::Range(1, kMaxSpp));
    sub->add_option("--partition", o->plan.slurm.partition, "Slurm partition (sbatch --partition)");
    sub->add_option("--account", o->plan.slurm.account, "Slurm account (sbatch --account)");
    sub->add_option("--time", o->plan.slurm.time, "Time limit of one task (sbatch --time), e.g. 1:00:00");
    sub->add_option("--cpus-per-task", o->plan.slurm.cpusPerTask, "CPUs of one task; its render threads (default 1)")
        ->check(CLI::Range(1, 4096));
    sub->add_option("--sbatch-arg", o->plan.slurm.extra,
                    "A further sbatch option, e.g. --sbatch-arg=--mem=4G (repeatable)")
        ->allow_extra_args(false);
    sub->add_option("--fraktal", o->plan.fraktal, "The fraktal program on the nodes (default: this one's path)");
    sub->add_flag("--dry-run", o->dryRun, "Write and print the scripts, submit nothing");
    sub->callback([&action, o] { action = [o] { return runSubmit(*o); }; });

    auto dir = std::make_shared<std::string>();
    CLI::App* status = farm->add_subcommand(
        "status",
        "Done, missing and broken frames of a farm render (checked like a rerun does) and its jobs' queue state");
    status->add_option("dir", *dir, "The output folder (holding .farm/jobs.json)")->required();
    status->callback([&action, dir] { action = [dir] { return runStatus(*dir); }; });
}

}  // namespace fraktal::cli
