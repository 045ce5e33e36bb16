#pragma once
/// @file
/// Child processes of `rig sweep`: spawned with their output in a file. The local workers are
/// forked into process groups of their own (so that a stop reaches a run and what it started,
/// and a terminal's ^C reaches only the sweep, which forwards it as SIGTERM).

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rig::sweep {

/// Starts argv[0] (a path) with `argv`, stdout and stderr appended to `log_file`, stdin
/// /dev/null, the default signal dispositions; in a new process group if `new_group`. Returns
/// its pid, or -1 with `error` set.
pid_t spawn(const std::vector<std::string>& argv, const std::filesystem::path& log_file,
            std::string& error, bool new_group = false);

/// A child's end as an exit code: its exit status, or 128 + the signal that killed it.
int exit_code_of(int wait_status);

/// Waits for `pid` (restarting on EINTR) and returns exit_code_of its status; -1 on error.
int wait_for(pid_t pid);

/// This executable (/proc/self/exe).
std::filesystem::path self_exe();

}  // namespace rig::sweep
