#include "cli/child_process.h"
#include "cli/cmd_homogenise.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/case_file.h"
#include "cli/homogenise_plan.h"
#include "cli/runin_version.h"
#include "cli/staged_file.h"
#include "coupling/ave_time_reader.h"
#include "coupling/homogenise_curves.h"
#include "tribo/contact_model.h"
#include "coupling/state_law.h"

extern char **environ;  // mpi_environment()

namespace runin::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using coupling::cell_series;
using coupling::depth_grid;
using coupling::DepthCurves;
using coupling::resample_on_depth_grid;

struct Options {
  std::string case_path, output = "law.json", output_dir, cache_dir, lmp, deck, launcher;
  bool launcher_given = false;  // --launcher "" is an error, not the default
  int np = 0;  // 0: the number of cores
  std::string command_line;
};

// ---------------------------------------------------------------------------------------------------------------
// Processes

std::string quoted(const std::string &text) { return "\"" + text + "\""; }

bool is_executable_file(const fs::path &path) {
  std::error_code error;
  return access(path.c_str(), X_OK) == 0 && fs::is_regular_file(path, error);
}

// `name` as given if it holds a '/', else the first executable of that name on PATH; empty if none.
std::string find_executable(const std::string &name) {
  if (name.find('/') != std::string::npos) return is_executable_file(name) ? name : std::string();
  const char *path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    if (is_executable_file(candidate)) return candidate.string();
  }
  return {};
}

// The environment of every mpirun: Open MPI as root (containers, CI), oversubscription allowed, one thread per rank
// (as tools/run-pipeline and tests/lammps/run_deck.py); the caller's own settings win.
std::vector<std::string> mpi_environment() {
  std::map<std::string, std::string> env;
  for (char **e = environ; *e; ++e) {
    const std::string entry(*e);
    const auto eq = entry.find('=');
    if (eq != std::string::npos) env[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  if (geteuid() == 0) {
    env.emplace("OMPI_ALLOW_RUN_AS_ROOT", "1");
    env.emplace("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1");
  }
  env.emplace("OMPI_MCA_rmaps_base_oversubscribe", "1");
  env.emplace("OMP_NUM_THREADS", "1");
  std::vector<std::string> out;
  for (const auto &[k, v] : env) out.push_back(k + "=" + v);
  return out;
}

std::string mpirun_program() {
  const char *env = std::getenv("RUNIN_MPIRUN");
  return env && *env ? env : "mpirun";
}

// How every LAMMPS run starts: the launcher's words ({np}: the ranks), then lmp_runin and its arguments. The
// default, $RUNIN_MPIRUN (else mpirun) -np {np} --oversubscribe, is the command runin has always run.
struct Launcher {
  std::vector<std::string> words;
  std::string name;  // what its errors name: --launcher, the case's key, RUNIN_MPIRUN
  bool is_default = false;
  std::vector<std::string> command(int np, const std::vector<std::string> &lmp_args) const {
    std::vector<std::string> args = expand_launcher(words, np);
    args.insert(args.end(), lmp_args.begin(), lmp_args.end());
    return args;
  }
  std::string program() const { return fs::path(words.front()).filename().string(); }
};

// --launcher, else the case's run.launcher, else the default.
Launcher resolve_launcher(const Options &o, const HomogeniseCase &c) {
  if (o.launcher_given) return {parse_launcher(o.launcher, "--launcher"), "--launcher", false};
  if (!c.launcher.empty()) return {c.launcher, c.path + ": key 'run.launcher'", false};
  return {{mpirun_program(), "-np", "{np}", "--oversubscribe"}, "RUNIN_MPIRUN", true};
}

// Starts `args` in `cwd` with stdout and stderr to `output`, in the mpirun environment; returns the pid.
pid_t spawn(const std::vector<std::string> &args, const Launcher &launcher, const fs::path &cwd,
            const fs::path &output) {
  ChildStreams streams;
  streams.stdout_file = output;
  streams.working_directory = cwd;
  try {
    return start_child(args, streams, mpi_environment());
  } catch (const std::runtime_error &) {
    throw std::runtime_error("cannot start " + args.front() +
                             (launcher.is_default ? " (set RUNIN_MPIRUN to the mpirun to use)"
                                                  : " (" + launcher.name + ")"));
  }
}

// SIGINT/SIGTERM/SIGHUP while samples run: the handler only records the signal; the polling loops forward it to
// the running mpiruns (which stop their ranks), wait for them and stop with one line. Finished samples stay cached.
volatile std::sig_atomic_t g_interrupt = 0;
extern "C" void record_interrupt(int signal) { g_interrupt = signal; }

class InterruptGuard {
 public:
  InterruptGuard() {
    struct sigaction action {};
    action.sa_handler = record_interrupt;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &action, &previous_[i]);
  }
  ~InterruptGuard() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &previous_[i], nullptr);
  }
  InterruptGuard(const InterruptGuard &) = delete;
  InterruptGuard &operator=(const InterruptGuard &) = delete;

 private:
  static constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> previous_{};
};

// After a recorded signal: terminate the children, reap them and throw (runin exits 1 naming the signal).
void stop_if_interrupted(const std::vector<pid_t> &children) {
  if (!g_interrupt) return;
  const int signal = g_interrupt;
  for (pid_t pid : children) kill(pid, SIGTERM);
  for (pid_t pid : children) {
    int status = 0;
    waitpid(pid, &status, 0);
  }
  throw std::runtime_error(fmt::format("interrupted by signal {} ({}): the running samples were stopped; the "
                                       "finished ones are cached, a rerun continues from them",
                                       signal, strsignal(signal)));
}

std::string first_line_starting(const fs::path &file, const std::string &prefix) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return {};
}

// ---------------------------------------------------------------------------------------------------------------
// Samples in the cache

std::string g17(double x) { return fmt::format("{:.17g}", x); }

// The sample's include file: its log, its variables (index variables are not redefined by a second `variable X
// index`, so each is deleted first), the deck, then `clear` for the next sample of the partition.
void prepare_sample(const HomogeniseCase &c, const Sample &s, const fs::path &deck) {
  fs::create_directories(s.dir);
  std::error_code ignore;
  fs::remove(s.dir / "out.dat.part", ignore);
  std::vector<std::pair<std::string, std::string>> vars = {
      {"material", c.material_file}, {"rough", c.rough},         {"counterface", c.counterface},
      {"R", g17(c.R)},               {"sigma", g17(c.sigma)},    {"spacing", g17(c.spacing)},
      {"nside", std::to_string(s.nside)}, {"pressure", g17(s.pressure)}, {"speed", g17(c.speed)},
      {"seed", std::to_string(s.seed)},   {"accel", g17(s.acceleration * c.wear_scale)}, {"depth", g17(c.depth)},
      {"nslide", std::to_string(c.nslide)}, {"nout", std::to_string(c.nout)}, {"out", s.output().string()},
  };
  if (!c.heights_file.empty()) vars.insert(vars.end(), {{"height_source", "list"}, {"heights", c.heights_file}});
  if (c.caps) vars.emplace_back("caps", "yes");
  if (c.vertical_drag) vars.emplace_back("vertical_drag", "yes");
  if (!c.contact_json().is_null()) {
    vars.emplace_back("friction", c.friction);
    if (!c.interface.empty()) vars.emplace_back("interface", c.interface);
  }
  if (c.jump_max_depth > 0.0)    // M unbounded: the mean depth per jump sets each jump
    vars.insert(vars.end(), {{"jump", "1e12"}, {"jump_every", std::to_string(c.jump_every)},
                             {"jump_max_depth", g17(c.jump_depth_at(s.pressure))}});
  if (c.jump_max_change > 0.0) vars.emplace_back("jump_max_change", g17(c.jump_max_change));
  if (c.jump_rate > 0.0) vars.emplace_back("jump_rate", g17(c.jump_rate));
  std::string text = "# runin homogenise: sample " + s.key + " (" + s.label() + ")\n";
  text += "log " + quoted(s.log().string()) + "\n";
  text += "print \"$(version)\" file " + quoted((s.dir / "lammps_version").string()) + " screen no\n";
  for (const auto &[name, value] : vars)
    text += fmt::format("variable {} delete\nvariable {} index {}\n", name, name, quoted(value));
  text += "include " + quoted(deck.string()) + "\nclear\n";
  StagedFile vars_file(s.dir / "sample.in");
  vars_file.write(text);
  vars_file.commit();
  StagedFile inputs(s.dir / "inputs.json");
  inputs.write(s.inputs.dump(2) + "\n");
  inputs.commit();
}

struct Failure {
  const Sample *sample;
  std::string error;
};

// A scratch directory for one mpirun (uloop's tmp.lammps.variable lives in the working directory).
fs::path make_workdir(const fs::path &cache_dir) {
  const fs::path runs = cache_dir / "runs";
  fs::create_directories(runs);
  for (int i = 0;; ++i) {
    const fs::path dir = runs / fmt::format("{}-{}-{}", std::time(nullptr), getpid(), i);
    std::error_code error;
    if (fs::create_directory(dir, error)) return dir;
    if (error) throw std::runtime_error("cannot create " + dir.string() + ": " + error.message());
  }
}

class Progress {
 public:
  Progress(std::vector<const Sample *> pending, std::size_t total, Clock::time_point start)
      : pending_(std::move(pending)), total_(total), start_(start) {}
  void poll() {
    for (auto it = pending_.begin(); it != pending_.end();) {
      if ((*it)->complete()) {
        ++done_;
        fmt::print("runin homogenise: sample {}/{} done: {} ({:.1f} s)\n", done_, total_, (*it)->label(),
                   std::chrono::duration<double>(Clock::now() - start_).count());
        std::fflush(stdout);
        it = pending_.erase(it);
      } else {
        ++it;
      }
    }
  }
  std::size_t done() const { return done_; }

 private:
  std::vector<const Sample *> pending_;
  std::size_t total_, done_ = 0;
  Clock::time_point start_;
};

// All `todo` samples under one mpirun: N partitions of one rank each, a uloop over the samples. Returns mpirun's
// exit status. An ERROR in one partition aborts the whole mpirun (lmp_runin turns LAMMPS's partition-mode abort
// exception into MPI_Abort); what completed before stays in the cache.
int run_partitioned(const std::vector<const Sample *> &todo, int n, const Launcher &launcher, const std::string &lmp,
                    const fs::path &cache_dir, Progress &progress) {
  const fs::path work = make_workdir(cache_dir);
  for (std::size_t k = 0; k < todo.size(); ++k) {
    std::ofstream f(work / fmt::format("sample_{}.in", k + 1));
    f << "include " << quoted((todo[k]->dir / "sample.in").string()) << "\n";
  }
  {
    std::ofstream driver(work / "driver.in");
    driver << "# runin homogenise: " << todo.size() << " samples over " << n << " partitions\n"
           << "variable runin_sample uloop " << todo.size() << "\n"
           << "label runin_next\n"
           << "include sample_${runin_sample}.in\n"  // relative to the working directory: no $ in quotes
           << "next runin_sample\n"
           << "jump SELF runin_next\n";
    if (!driver) throw std::runtime_error("cannot write " + (work / "driver.in").string());
  }
  std::vector<std::string> lmp_args = {lmp};
  if (n > 1) lmp_args.insert(lmp_args.end(), {"-partition", fmt::format("{}x1", n)});
  lmp_args.insert(lmp_args.end(), {"-in", (work / "driver.in").string(), "-log", (work / "log.lammps").string(),
                                   "-screen", "none"});
  const std::vector<std::string> args = launcher.command(n, lmp_args);
  std::string shown;
  for (const auto &word : expand_launcher(launcher.words, n)) shown += word + " ";
  fmt::print("runin homogenise: {}... ({} samples, {} partitions; logs in each sample's directory)\n", shown,
             todo.size(), n);
  std::fflush(stdout);
  const InterruptGuard guard;
  const pid_t pid = spawn(args, launcher, work, work / "mpirun.out");
  std::optional<int> status;
  while (!(status = poll_child(pid))) {
    stop_if_interrupted({pid});
    progress.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  progress.poll();
  if (*status == 0) fs::remove_all(work);  // kept on failure: mpirun.out and the partition logs
  return *status;
}

// Each sample alone (its own mpirun -np 1), up to `n` at a time: a failing sample no longer takes the others down,
// and its log names its ERROR.
std::vector<Failure> run_isolated(const std::vector<const Sample *> &todo, int n, const Launcher &launcher,
                                  const std::string &lmp, const fs::path &cache_dir, Progress &progress) {
  const fs::path work = make_workdir(cache_dir);
  std::vector<Failure> failures;
  std::vector<std::pair<pid_t, std::size_t>> running;
  std::size_t next = 0;
  auto finish = [&](std::size_t k, int status) {
    const Sample &s = *todo[k];
    if (s.complete()) return;
    std::string error = first_line_starting(s.log(), "ERROR");
    if (error.empty()) error = last_line(work / fmt::format("sample_{}.out", k + 1));
    if (error.empty()) error = fmt::format("no output and no ERROR line (exit status {})", status);
    failures.push_back({&s, error});
  };
  const InterruptGuard guard;
  while (next < todo.size() || !running.empty()) {
    std::vector<pid_t> children;
    for (const auto &r : running) children.push_back(r.first);
    stop_if_interrupted(children);
    while (next < todo.size() && static_cast<int>(running.size()) < n) {
      const std::vector<std::string> args =
          launcher.command(1, {lmp, "-in", (todo[next]->dir / "sample.in").string(), "-log",
                               (work / fmt::format("sample_{}.log", next + 1)).string(), "-screen", "none"});
      running.emplace_back(spawn(args, launcher, work, work / fmt::format("sample_{}.out", next + 1)), next);
      ++next;
    }
    for (auto it = running.begin(); it != running.end();) {
      if (const auto status = poll_child(it->first)) {
        finish(it->second, *status);
        it = running.erase(it);
      } else {
        ++it;
      }
    }
    progress.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  if (failures.empty()) fs::remove_all(work);
  return failures;
}

// ---------------------------------------------------------------------------------------------------------------

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

fs::path default_cache_dir() {
  if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "runin" / "homogenise";
  if (const char *home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "runin" / "homogenise";
  return fs::path(".runin-cache") / "homogenise";
}

// A path for the law's provenance, valid on any machine: relative to the RunIn source tree when inside it, else
// the file's name alone (the SHA-256 beside it identifies the content); never an absolute path of this machine.
std::string portable_path(const fs::path &path) {
  std::error_code error;
  const fs::path full = fs::weakly_canonical(fs::absolute(path), error);
  const fs::path source = fs::weakly_canonical(fs::path(RUNIN_SOURCE_DIR), error);
  const fs::path relative = full.lexically_relative(source);
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return full.filename().string();
}

// The command line with every absolute path (also in --option=/path) made portable.
std::string portable_command_line(const std::string &command_line) {
  std::istringstream words(command_line);
  std::string out;
  for (std::string word; words >> word;) {
    const auto equals = word.find('=');
    if (!word.empty() && word[0] == '/')
      word = portable_path(word);
    else if (equals != std::string::npos && equals + 1 < word.size() && word[equals + 1] == '/')
      word = word.substr(0, equals + 1) + portable_path(word.substr(equals + 1));
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

// --deck, else the case's `deck`, else the rough-on-rough cell of the pipeline (the rough-on-flat in.rve_wall's
// friction does not run in)
fs::path resolve_deck(const Options &o, const HomogeniseCase &c) {
  const fs::path deck = fs::absolute(!o.deck.empty()          ? fs::path(o.deck)
                                     : !c.deck_file.empty() ? fs::path(c.deck_file)
                                                            : fs::path(RUNIN_SOURCE_DIR) / "inputs" / "in.rve_rough");
  std::error_code error;
  if (!fs::is_regular_file(deck, error)) throw InputError("--deck: not a file: " + deck.string());
  return deck;
}

// --lmp, else lmp_runin beside runin, else on PATH; absolute.
std::string resolve_lmp(const Options &o) {
  std::string lmp = o.lmp;
  if (lmp.empty()) {
    std::error_code error;
    const fs::path beside = fs::read_symlink("/proc/self/exe", error).parent_path() / "lmp_runin";
    lmp = !error && access(beside.c_str(), X_OK) == 0 ? beside.string() : find_executable("lmp_runin");
    if (lmp.empty())
      throw InputError("--lmp: lmp_runin is neither beside runin nor on PATH; give --lmp PATH (LAMMPS with the "
                       "RunIn styles)");
  } else {
    const std::string found = find_executable(lmp);
    if (found.empty()) throw InputError("--lmp: not an executable: " + lmp);
    lmp = found;
  }
  return fs::absolute(lmp).string();
}

// What the case asks of the deck: a summit list reader, an acceleration-invariant cell for accelerated wear.
void check_deck(const HomogeniseCase &c, const fs::path &deck, const std::string &deck_text) {
  if (!c.heights_file.empty() && deck_text.find("height_source") == std::string::npos)
    throw InputError(c.path + ": key 'surface.heights': the deck " + deck.string() +
                     " does not read a summit list (it has no height_source variable; inputs/in.rve_wall does)");
  if (!c.contact_json().is_null() && deck_variable(deck_text, "interface").empty())
    throw InputError(c.path + ": key 'contact.friction': the deck " + deck.string() +
                     " takes no friction model or interface state (it has no interface variable; inputs/in.rve_rough "
                     "and inputs/in.rve_wall do)");
  if (c.vertical_drag && deck_variable(deck_text, "vertical_drag").empty())
    throw InputError(c.path + ": key 'sliding.vertical_drag': the deck " + deck.string() +
                     " has no vertical_drag variable (inputs/in.rve_rough has)");
  if (c.caps && deck_variable(deck_text, "caps").empty())
    throw InputError(c.path + ": key 'surface.caps': the deck " + deck.string() +
                     " has no caps variable (inputs/in.rve_rough has: pair_style runin/asperity caps)");
  if (c.jump_max_depth > 0.0 && deck_variable(deck_text, "jump").empty())
    throw InputError(c.path + ": key 'wear.jump_max_depth': the deck " + deck.string() +
                     " does not support cycle jumping (it has no jump variable; inputs/in.rve_rough does)");
  if (c.jump_max_change > 0.0 && deck_variable(deck_text, "jump_max_change").empty())
    throw InputError(c.path + ": key 'wear.jump_max_change': the deck " + deck.string() +
                     " has no jump_max_change variable (inputs/in.rve_rough has)");
  if (c.jump_rate > 0.0 && deck_variable(deck_text, "jump_rate").empty())
    throw InputError(c.path + ": key 'wear.jump_rate': the deck " + deck.string() +
                     " has no jump_rate variable (inputs/in.rve_rough has)");
  // accelerated wear is valid only in a cell whose law in h does not depend on it; the deck says so
  const double top = *std::max_element(c.acceleration.begin(), c.acceleration.end());
  if (top > 1.0 && deck_variable(deck_text, "accel_invariant") != "yes")
    throw InputError(fmt::format("{}: key 'grid.acceleration': {:g} > 1, but the deck {} is not acceleration-"
                                 "invariant (it does not declare `variable accel_invariant index yes`); use "
                                 "acceleration = 1, or a deck that is (--deck inputs/in.rve_wall, or the case's "
                                 "deck key)",
                                 c.path, top, deck.string()));
}

// The MPI launcher, before any sample starts (a fully cached rerun needs none), and the cache directory. A
// launcher path with a '/' is made absolute: the runs start in a scratch directory.
void check_launcher_and_cache(bool samples_to_run, Launcher &launcher, const fs::path &cache_dir) {
  const std::string program = launcher.words.front();
  const std::string found = samples_to_run ? find_executable(program) : program;
  if (found.empty() && launcher.is_default)
    throw InputError(std::getenv("RUNIN_MPIRUN") && *std::getenv("RUNIN_MPIRUN")
                         ? "RUNIN_MPIRUN: not an executable: " + mpirun_program() +
                               "; set it to the MPI launcher (mpirun or mpiexec) or unset it"
                         : "RUNIN_MPIRUN: mpirun is not on PATH; install an MPI (Open MPI, MPICH) or set RUNIN_MPIRUN "
                           "to its launcher (e.g. mpiexec)");
  if (found.empty())
    throw InputError(launcher.name + ": " + program + " is not an executable" +
                     (program.find('/') == std::string::npos ? " on PATH" : "") +
                     "; name the MPI launcher (mpirun, mpiexec, srun) or give its path");
  if (program.find('/') != std::string::npos) launcher.words.front() = fs::absolute(found).string();
  std::error_code error;
  fs::create_directories(cache_dir, error);
  if (error || !fs::is_directory(cache_dir))
    throw std::runtime_error("cannot create the cache directory " + cache_dir.string() +
                             (error ? ": " + error.message() : std::string()));
}

// Runs the samples not in the cache: all under one mpirun, then each missing one alone to name the failing ones.
std::vector<Failure> run_samples(const HomogeniseCase &c, const std::vector<const Sample *> &todo, int np,
                                 const Launcher &launcher, const std::string &lmp, const fs::path &deck,
                                 const fs::path &cache_dir, Clock::time_point start) {
  std::vector<Failure> failures;
  if (todo.empty()) return failures;
  for (const Sample *s : todo) prepare_sample(c, *s, deck);
  Progress progress(todo, todo.size(), start);
  const int status = run_partitioned(todo, np, launcher, lmp, cache_dir, progress);
  std::vector<const Sample *> missing;
  for (const Sample *s : todo)
    if (!s->complete()) missing.push_back(s);
  if (missing.size() == 1 && todo.size() == 1) {
    // it ran alone already: its log names the ERROR
    std::string error = first_line_starting(missing.front()->log(), "ERROR");
    if (error.empty())
      error = fmt::format("no output and no ERROR line in its log ({} exit status {})", launcher.program(), status);
    failures.push_back({missing.front(), error});
  } else if (!missing.empty()) {
    fmt::print("runin homogenise: {} exited with status {}, {} samples incomplete; running each alone to find "
               "the failing ones\n",
               launcher.program(), status, missing.size());
    std::fflush(stdout);
    failures = run_isolated(missing, std::min<int>(np, static_cast<int>(missing.size())), launcher, lmp, cache_dir,
                            progress);
  }
  return failures;
}

// Each complete sample on the h grid (its contact fraction over its own cell's summits); a sample that cannot be read
// or did not reach the depth fails too.
std::map<const Sample *, DepthCurves> read_curves(const std::vector<Sample> &samples, const std::vector<double> &grid,
                                                   std::vector<Failure> &failures) {
  std::map<const Sample *, DepthCurves> curves;
  for (const auto &s : samples) {
    if (!s.complete()) continue;
    try {
      const double rough_summits = static_cast<double>(s.nside) * static_cast<double>(s.nside);
      curves.emplace(&s, resample_on_depth_grid(cell_series(coupling::read_ave_time(s.output().string()), rough_summits),
                                                grid, s.acceleration));
    } catch (const std::exception &e) {
      failures.push_back({&s, e.what()});
    }
  }
  for (const auto &f : failures)
    fmt::print("runin homogenise: sample FAILED: {} (accel {:g}, key {}): {}; log {}\n", f.sample->label(),
               f.sample->acceleration, f.sample->key, f.error, f.sample->log().string());  // stderr: the one error line
  return curves;
}

std::string failed_labels(const std::vector<Failure> &failures) {
  std::string list;
  for (const auto &f : failures) list += (list.empty() ? "" : "; ") + f.sample->label();
  return list;
}

// The good seeds of each pressure (coupling::homogenise averages them); every pressure needs at least one.
coupling::HomogenisationSamples good_seeds(const HomogeniseCase &c, const std::vector<Sample> &samples,
                                           const std::vector<double> &grid,
                                           const std::map<const Sample *, DepthCurves> &curves,
                                           const std::vector<Failure> &failures) {
  coupling::HomogenisationSamples good{c.pressures, grid, {}};
  std::vector<std::size_t> empty_pressures;
  for (std::size_t ip = 0; ip < c.pressures.size(); ++ip) {
    good.seeds.emplace_back();
    for (const auto &s : samples)
      if (s.ip == ip && curves.count(&s)) good.seeds.back().push_back(curves.at(&s));
    if (good.seeds.back().empty()) empty_pressures.push_back(ip);
  }
  if (empty_pressures.empty()) return good;
  std::string list;
  for (std::size_t ip : empty_pressures) list += (list.empty() ? "" : ", ") + fmt::format("{:.4g}", c.pressures[ip]);
  throw std::runtime_error(fmt::format("homogenise: no law written: no good seed at p = {} Pa; {} of {} samples "
                                       "failed: {}",
                                       list, failures.size(), samples.size(), failed_labels(failures)));
}

struct Provenance {
  fs::path deck, cache_dir;
  std::string deck_text;
  CodeIdentity code;  // the LAMMPS executable: path, SHA-256 and physics identity
};

// The law's record of the LAMMPS executable: its path and SHA-256, and its physics identity when it has one.
nlohmann::json lmp_metadata(const CodeIdentity &code) {
  nlohmann::json lmp = {{"path", portable_path(code.lmp_path)}, {"sha256", code.lmp_sha256}};
  if (!code.physics_sha256.empty()) lmp["physics_sha256"] = code.physics_sha256;
  return lmp;
}

// The LAMMPS version line of the first good sample that recorded one.
std::string lammps_version(const std::vector<Sample> &samples, const std::map<const Sample *, DepthCurves> &curves) {
  for (const auto &s : samples)
    if (curves.count(&s)) {
      std::ifstream in(s.dir / "lammps_version");
      std::string line;
      if (std::getline(in, line) && !line.empty()) return line;
    }
  return "unknown";
}

nlohmann::json sample_list(const std::vector<Sample> &samples, const std::vector<Failure> &failures) {
  std::map<const Sample *, std::string> failed;
  for (const auto &f : failures) failed[f.sample] = f.error;
  nlohmann::json list = nlohmann::json::array();
  for (const auto &s : samples) {
    nlohmann::json entry = {{"pressure", s.pressure}, {"seed", s.seed}, {"acceleration", s.acceleration},
                            {"key", s.key}, {"status", failed.count(&s) ? "failed" : "ok"}};
    if (failed.count(&s)) entry["error"] = failed.at(&s);
    list.push_back(entry);
  }
  return list;
}

nlohmann::json law_metadata(const Options &o, const HomogeniseCase &c, const Provenance &p,
                            const std::vector<Sample> &samples, const std::map<const Sample *, DepthCurves> &curves,
                            const std::vector<Failure> &failures) {
  nlohmann::json metadata = {
      {"title", c.title},
      {"material",
       {{"file", portable_path(c.material_file)}, {"sha256", sha256_hex(file_bytes(c.material_file))}, {"rough", c.rough},
        {"counterface", c.counterface}}},
      {"surface",
       {{"R", c.R}, {"sigma", c.sigma}, {"spacing", c.spacing}, {"nside", c.nside}, {"summits", c.nside * c.nside}}},
      {"speed", c.speed},
      {"samples",
       {{"seeds", c.seeds},
        {"acceleration", c.acceleration},
        {"depth", c.depth},
        {"depth_spacing", c.depth_first > 0.0 ? "geometric" : "linear"},
        {"nslide", c.nslide},
        {"nout", c.nout},
        {"band", "low/high: minimum/maximum over the good seeds at each point; mean: their mean"},
        {"deck", {{"path", portable_path(p.deck)}, {"sha256", sha256_hex(p.deck_text)}}},
        {"cache_dir", portable_path(p.cache_dir)},
        {"list", sample_list(samples, failures)}}},
      {"provenance",
       {{"runin_version", runin_version()},
        {"runin_git", runin_git_describe()},
        {"lammps_version", lammps_version(samples, curves)},
        {"lmp", lmp_metadata(p.code)},
        {"command_line", portable_command_line(o.command_line)},
        {"case", {{"path", portable_path(o.case_path)},
                  {"sha256", sha256_hex(file_bytes(o.case_path))}}},
        {"date_utc", utc_now()},
        {"host", host_name()}}},
  };
  if (c.caps) metadata["surface"]["caps"] = true;
  if (c.vertical_drag) metadata["vertical_drag"] = true;
  if (std::any_of(c.nside_at.begin(), c.nside_at.end(), [&](long n) { return n != c.nside; }))
    metadata["surface"]["nside_at_pressure"] = c.nside_at;    // larger cells below the grid (grid.extra_nside)
  if (const nlohmann::json wear = c.wear_json(); !wear.is_null()) metadata["samples"]["wear"] = wear;
  if (nlohmann::json contact = c.contact_json(); !contact.is_null()) {
    // a law that takes the state's m as its f: its coefficients as the deck's file form gives them (f = m, the
    // others at their defaults), for an element's surface film
    const tribo::SubModelInfo &law = c.friction_info();
    if (law.interface_use == tribo::InterfaceUse::interface_coefficient) {
      tribo::ContactParameters p;
      p.interface_coefficient = c.interface_factor;
      const tribo::Coefficients values = tribo::friction_coefficients_from(
          tribo::find_sub_model(tribo::SubModelKind::friction, c.friction), p);
      for (std::size_t k = 0; k < values.size(); ++k) contact[law.coefficient_names[k]] = values[k];
    }
    metadata["samples"]["contact"] = contact;
  }
  if (!c.heights_file.empty()) {
    metadata["surface"]["heights"] = portable_path(c.heights_file);
    metadata["surface"]["heights_sha256"] = c.heights_sha256;
  }
  return metadata;
}

void write_law(const Options &o, const coupling::HomogenisationSamples &good) {
  const coupling::StateLaw law = [&] {
    try {
      return coupling::homogenise(good);
    } catch (const std::invalid_argument &e) {
      throw std::runtime_error(std::string("homogenise: the samples give no valid state law: ") + e.what());
    }
  }();
  if (!o.output_dir.empty()) {
    std::error_code error;
    fs::create_directories(o.output_dir, error);
    if (error) throw std::runtime_error("cannot create --output-dir " + o.output_dir + ": " + error.message());
  }
  StagedFile out(fs::absolute(o.output));
  out.write(law.to_json().dump(1) + "\n");
  out.commit();
}

int run_homogenise(const Options &o) {
  const auto start = Clock::now();
  const HomogeniseCase c = read_homogenise_case(o.case_path, !o.deck.empty());
  if (o.np < 0) throw InputError("--np: must be positive");
  Launcher launcher = resolve_launcher(o, c);
  Provenance p;
  p.deck = resolve_deck(o, c);
  const std::string lmp = resolve_lmp(o);
  p.deck_text = file_bytes(p.deck);
  check_deck(c, p.deck, p.deck_text);
  p.cache_dir = fs::absolute(o.cache_dir.empty() ? default_cache_dir() : fs::path(o.cache_dir));
  p.code = CodeIdentity{runin_version(), lmp, sha256_hex(file_bytes(lmp)), lmp_physics_identity(lmp)};
  const CodeIdentity &code = p.code;
  if (code.physics_sha256.empty())
    fmt::print("runin homogenise: note: no {}.physics beside it: the samples are keyed on the executable's SHA-256 "
               "(any relink reruns them)\n",
               fs::path(lmp).filename().string());
  const std::vector<Sample> samples = plan_samples(c, p.deck_text, code, p.cache_dir);
  std::vector<const Sample *> todo;
  for (const auto &s : samples)
    if (!s.complete()) todo.push_back(&s);
  check_launcher_and_cache(!todo.empty(), launcher, p.cache_dir);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int np = static_cast<int>(std::min<std::size_t>(o.np > 0 ? o.np : cores, std::max<std::size_t>(1, todo.size())));
  std::string larger_cells;
  for (std::size_t ip = 0; ip < c.pressures.size(); ++ip)
    if (c.nside_at[ip] != c.nside)
      larger_cells += fmt::format("{}{} at {:.4g} Pa", larger_cells.empty() ? " (" : ", ", c.nside_at[ip] * c.nside_at[ip],
                                  c.pressures[ip]);
  if (!larger_cells.empty()) larger_cells += ")";
  fmt::print("runin homogenise: {}: {} pressures x {} seeds = {} samples of {} summits{}; {} cached in {}\n",
             o.case_path, c.pressures.size(), c.seeds.size(), samples.size(), c.nside * c.nside, larger_cells,
             samples.size() - todo.size(), p.cache_dir.string());
  fmt::print("runin homogenise: {} samples to run\n", todo.size());
  std::fflush(stdout);

  std::vector<Failure> failures = run_samples(c, todo, np, launcher, lmp, p.deck, p.cache_dir, start);
  const std::vector<double> grid = depth_grid(c.depth, c.depth_points, c.depth_first);
  const auto curves = read_curves(samples, grid, failures);
  coupling::HomogenisationSamples good = good_seeds(c, samples, grid, curves, failures);
  good.metadata = law_metadata(o, c, p, samples, curves, failures);
  write_law(o, good);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  fmt::print("runin homogenise: wrote {} ({} pressures {:.4g} .. {:.4g} Pa x {} depths 0 .. {:.4g} m, {} seeds; "
             "{:.2f} s)\n",
             o.output, c.pressures.size(), c.pressures.front(), c.pressures.back(), grid.size(), c.depth,
             c.seeds.size(), seconds);
  if (!failures.empty())
    throw std::runtime_error(fmt::format("homogenise: {} of {} samples failed (the law uses the other seeds): {}",
                                         failures.size(), samples.size(), failed_labels(failures)));
  return 0;
}

}  // namespace

Subcommand add_homogenise_command(CLI::App &app) {
  auto o = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("homogenise",
                                 "Sample the rough cell (default inputs/in.rve_rough, rough on rough) over a pressure grid "
                                 "and seeds (LAMMPS partitions) and write the state law");
  cmd->add_option("case", o->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  auto *output = cmd->add_option("--output", o->output, "state law file to write (JSON)")
                     ->capture_default_str()
                     ->check(non_empty_path());
  // the elements' spelling: the law goes to DIR/law.json
  cmd->add_option("--output-dir", o->output_dir, "directory to write law.json into (instead of --output)")
      ->check(output_directory())
      ->excludes(output);
  cmd->add_option("--cache-dir", o->cache_dir,
                  "sample cache (default $XDG_CACHE_HOME/runin/homogenise, else ~/.cache/runin/homogenise)")
      ->check(non_empty_path());
  cmd->add_option("--np", o->np, "MPI ranks = LAMMPS partitions (default: the number of cores)")
      ->check(CLI::Range(1, 100000));
  auto *launcher = cmd->add_option(
      "--launcher", o->launcher,
      "MPI launcher of the LAMMPS runs, split at blanks (no shell), {np} = ranks; e.g. \"srun -n {np}\" (default: "
      "the case's run.launcher, else $RUNIN_MPIRUN or mpirun, -np {np} --oversubscribe)");
  cmd->add_option("--lmp", o->lmp, "LAMMPS executable with the RunIn styles (default: lmp_runin beside runin)");
  cmd->add_option("--deck", o->deck,
                  "cell deck (default: the case's `deck`, else inputs/in.rve_rough of the RunIn source tree, the "
                  "rough-on-rough cell; inputs/in.rve_wall is the rough-on-flat one)");
  return {cmd, [o, launcher] {
            // the command line as run, for the provenance: /proc/self/cmdline (NUL-separated)
            std::ifstream in("/proc/self/cmdline", std::ios::binary);
            for (std::string arg; std::getline(in, arg, '\0');) o->command_line += (o->command_line.empty() ? "" : " ") + arg;
            if (!o->output_dir.empty()) o->output = (fs::path(o->output_dir) / "law.json").string();
            o->launcher_given = launcher->count() > 0;
            return run_homogenise(*o);
          }};
}

}  // namespace runin::cli
