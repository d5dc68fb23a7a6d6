// A page starts no process: posix_spawnp for the support library (cmake/support/process.cpp)
// fails with ENOSYS, and the caller reports it. The live modules never ask for one (they run
// their scene with --no-figure, so --motion draws no GIF).
#include <errno.h>
#include <spawn.h>

int posix_spawnp(pid_t* pid, const char* file, const posix_spawn_file_actions_t* actions, const posix_spawnattr_t* attr,
                 char* const argv[], char* const envp[]) {
    (void)pid, (void)file, (void)actions, (void)attr, (void)argv, (void)envp;
    return ENOSYS;
}
