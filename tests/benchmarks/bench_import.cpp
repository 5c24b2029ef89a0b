// Figures for `session import` and `report` of armtrack-cli on hostile files and on an hour at
// 1 kHz (docs/storage.md, "Memory and time of an analysis"; a re-estimate's speed is
// bench_storage's BM_Reestimate): each command runs as a child process, and its wall time, CPU
// and peak resident memory (the kernel's ru_maxrss) are printed beside the target. Not a test:
// timings depend on the machine; the tests check the behaviour.
//
//   bench_import --cli build/app/armtrack-cli [--minutes 60] [--skip-hour] [--trunk-hour]
//                [--dir DIR]
// --trunk-hour adds the hour's re-estimation with a sternum IMU and a leaning trunk (issue 26):
// `estimate` of the same hour simulated with the trunk, against the one without.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Run {
  int exitCode = -1;
  double seconds = 0;
  double cpuSeconds = 0;  // user + system
  double peakMb = 0;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs argv with the environment plus ARMTRACK_PASSWORD; standard output and error to files.
Run run(const std::vector<std::string>& argv, const fs::path& dir) {
  const fs::path outFile = dir / "child.out", errFile = dir / "child.err";
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    std::perror("exec");
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peakMb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
  r.cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                 1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(outFile);
  r.err = slurp(errFile);
  return r;
}

std::string lastLine(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  const auto nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

void print(const std::string& what, const Run& r, double maxSeconds, double maxMb) {
  const bool ok = r.seconds <= maxSeconds && r.peakMb <= maxMb;
  std::printf("%-40s exit %3d  %7.2f s (target %5.1f; CPU %6.2f s)  %7.1f MB (target %4.0f)  %s\n",
              what.c_str(), r.exitCode, r.seconds, maxSeconds, r.cpuSeconds, r.peakMb, maxMb,
              ok ? "within" : "OVER");
  std::printf("    %s\n", lastLine(r.err).c_str());
  std::fflush(stdout);
}

// Replaces the time of data row `row` (1-based, after the header) and every later row by t +
// shift, or sets row `row`'s time to `absolute` when given.
void editTimes(const fs::path& in, const fs::path& out, std::size_t row, double shift,
               const char* absolute) {
  std::ifstream src(in);
  std::ofstream dst(out);
  std::string line;
  std::size_t n = 0;
  while (std::getline(src, line)) {
    if (line.empty() || line[0] == '#' || n++ == 0) {
      dst << line << '\n';
      continue;
    }
    const std::size_t dataRow = n - 1;
    const auto comma = line.find(',');
    if (dataRow == row && absolute) {
      dst << absolute << line.substr(comma) << '\n';
    } else if (dataRow >= row && shift != 0) {
      char t[64];
      std::snprintf(t, sizeof t, "%.17g", std::strtod(line.c_str(), nullptr) + shift);
      dst << t << line.substr(comma) << '\n';
    } else {
      dst << line << '\n';
    }
  }
  fs::copy_file(fs::path(in).replace_extension(".json"), fs::path(out).replace_extension(".json"),
                fs::copy_options::overwrite_existing);
}

}  // namespace

int main(int argc, char** argv) {
  std::string cli;
  double minutes = 60;
  bool hour = true, trunkHour = false;
  fs::path dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cli" && i + 1 < argc)
      cli = argv[++i];
    else if (a == "--minutes" && i + 1 < argc)
      minutes = std::atof(argv[++i]);
    else if (a == "--skip-hour")
      hour = false;
    else if (a == "--trunk-hour")
      trunkHour = true;
    else if (a == "--dir" && i + 1 < argc)
      dir = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: bench_import --cli PATH [--minutes N] [--skip-hour] [--trunk-hour] "
                   "[--dir D]\n");
      return 2;
    }
  }
  if (cli.empty() || !fs::exists(cli)) {
    std::fprintf(stderr, "bench_import: give the armtrack-cli binary with --cli\n");
    return 2;
  }
  cli = fs::absolute(cli);
  const bool ownDir = dir.empty();
  if (ownDir) {
    char tmpl[] = "/tmp/armtrack-bench-import-XXXXXX";
    dir = ::mkdtemp(tmpl);
  }
  ::setenv("ARMTRACK_PASSWORD", "bench-password-1", 1);
  const std::string db = (dir / "clinic.db").string();
  const auto tool = [&](std::vector<std::string> args) {
    args.insert(args.begin(), cli);
    return run(args, dir);
  };
  Run r = tool({"db", "init", "--db", db, "--admin", "boss"});
  if (r.exitCode != 0) {
    std::fprintf(stderr, "db init failed: %s\n", r.err.c_str());
    return 1;
  }
  tool({"patient", "add", "--db", db, "--user", "boss", "--code", "P01", "--name", "Bench"});
  const auto import = [&](const fs::path& csv) {
    return tool(
        {"session", "import", csv.string(), "--patient", "P01", "--db", db, "--user", "boss"});
  };

  std::printf("session import of hostile files (each refused, or stored with its gaps):\n");
  const fs::path five = dir / "five.csv";
  tool({"simulate", "--trajectory", "multi-joint", "--duration", "5", "--out", five.string()});
  editTimes(five, dir / "day-jump.csv", 2500, 86400.0, nullptr);
  print("5 s with a one-day jump at row 2,500", import(dir / "day-jump.csv"), 10, 300);
  editTimes(five, dir / "hour-jump.csv", 2500, 3600.0, nullptr);
  print("5 s with a one-hour jump at row 2,500", import(dir / "hour-jump.csv"), 10, 300);
  editTimes(five, dir / "absurd.csv", 2500, 0, "1e300");
  print("5 s with t = 1e300 at row 2,500", import(dir / "absurd.csv"), 10, 300);
  {
    const fs::path sparse = dir / "sparse.csv";
    std::ofstream(sparse).close();
    fs::resize_file(sparse, std::uintmax_t{2} << 30);
    print("a 2 GB sparse file", import(sparse), 10, 300);
    fs::remove(sparse);
  }
  {
    const fs::path nuls = dir / "nuls.csv";
    std::ifstream src(five);
    std::string header;
    std::getline(src, header);
    while (!header.empty() && header[0] == '#') std::getline(src, header);
    std::ofstream dst(nuls, std::ios::binary);
    dst << header << '\n';
    const std::string block(1 << 20, '\0');
    for (int i = 0; i < 100; ++i)
      dst.write(block.data(), static_cast<std::streamsize>(block.size()));
    dst.close();
    fs::copy_file(fs::path(five).replace_extension(".json"), dir / "nuls.json");
    print("a valid header and 100 MB of NULs", import(nuls), 10, 300);
    fs::remove(nuls);
  }

  if (hour) {
    const fs::path big = dir / "hour.csv";
    const std::string duration = std::to_string(static_cast<int>(minutes * 60));
    std::printf("\n%.0f min at 1 kHz (two IMUs, Kinect, true angles):\n", minutes);
    r = tool(
        {"simulate", "--trajectory", "multi-joint", "--duration", duration, "--out", big.string()});
    std::printf("%-44s exit %3d  %7.2f s  (%.0f MB of CSV)\n", "simulate", r.exitCode, r.seconds,
                static_cast<double>(fs::file_size(big)) / 1e6);
    const double scale = minutes / 60.0;
    const Run imported = import(big);
    print("session import (store and analyse)", imported, 20 * scale, 300);
    const std::string id = imported.out.substr(0, imported.out.find('\n'));
    print("report of that session (PDF)",
          tool({"report", id, "--pdf", (dir / "hour.pdf").string(), "--db", db, "--user", "boss"}),
          2 * scale, 300);
    fs::remove(big);
  }
  if (trunkHour) {
    const std::string duration = std::to_string(static_cast<int>(minutes * 60));
    const double scale = minutes / 60.0;
    std::printf(
        "\n%.0f min at 1 kHz re-estimated (two IMUs, Kinect), still trunk and leaning "
        "trunk with a sternum IMU:\n",
        minutes);
    for (const bool trunk : {false, true}) {
      const fs::path rec = dir / (trunk ? "trunk-hour.csv" : "still-hour.csv");
      std::vector<std::string> sim = {"simulate", "--trajectory", "reaching",  "--peak-rate",
                                      "90",       "--peak-accel", "300",       "--duration",
                                      duration,   "--out",        rec.string()};
      if (trunk) sim.insert(sim.end(), {"--trunk-lean", "15", "--trunk-imu"});
      r = tool(sim);
      std::printf("%-44s exit %3d  %7.2f s  (%.0f MB of CSV)\n",
                  trunk ? "simulate (trunk)" : "simulate (still)", r.exitCode, r.seconds,
                  static_cast<double>(fs::file_size(rec)) / 1e6);
      print(trunk ? "estimate, sternum IMU and leaning trunk" : "estimate, still trunk",
            tool({"estimate", rec.string(), "--out", (dir / "est.csv").string(), "--overwrite"}),
            60 * scale, 300);
      fs::remove(rec);
      fs::remove(fs::path(rec).replace_extension(".json"));
    }
  }
  if (ownDir) fs::remove_all(dir);
  return 0;
}
