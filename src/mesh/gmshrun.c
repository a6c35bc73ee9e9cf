/* Running Gmsh as a child process, optionally under a guard. Not system(),
   which ignores SIGINT while it waits, so that Ctrl-C during meshing would be
   lost; the child is in the same process group, so a terminal's Ctrl-C stops
   it too. posix_spawn rather than fork (which MPI warns of), so a guard's
   limits are set by a shell that then becomes Gmsh: `sh -c 'ulimit -t N &&
   ulimit -v K && exec "$0" "$@"' gmsh ...`; a run that passes its CPU limit
   gets SIGXCPU, one that passes its memory limit fails to allocate
   (std::bad_alloc: SIGABRT), and either dies of a signal, which is how a
   tripped guard is told from Gmsh's own errors (an exit status). */
#include <sys/wait.h>
#include <fcntl.h>
#include <spawn.h>
#include <unistd.h>
#include <errno.h>
#include <signal.h>
#include "gmshrun.h"
#include "outputset.h"

int GmshRun(char *const argv[], const char log[], const char out[], const GmshGuard *guard, PetscBool *tripped)
{
  extern char              **environ;
  posix_spawn_file_actions_t fa;
  pid_t                      pid;
  int                        st = 0, r, n = 0;
  char                       script[192], cpu[32] = "unlimited", mem[32] = "unlimited", *av[256];
  char *const               *run = argv;

  if (tripped) *tripped = PETSC_FALSE;
  if (guard) {
    while (argv[n]) ++n;
    if (n + 4 > (int)(sizeof(av) / sizeof(av[0]))) return -1;
    if (guard->cpuSeconds > 0) snprintf(cpu, sizeof(cpu), "%d", guard->cpuSeconds);
    if (guard->memoryBytes > 0) snprintf(mem, sizeof(mem), "%.0f", guard->memoryBytes / 1024);
    snprintf(script, sizeof(script), "ulimit -c 0 && ulimit -t %s && ulimit -v %s && exec \"$0\" \"$@\"", cpu, mem);
    av[0] = (char *)"sh";
    av[1] = (char *)"-c";
    av[2] = script;
    for (int i = 0; i <= n; ++i) av[3 + i] = argv[i];
    run = av;
  }
  if (posix_spawn_file_actions_init(&fa)) return -1;
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  r = posix_spawnp(&pid, run[0], &fa, NULL, run, environ);
  posix_spawn_file_actions_destroy(&fa);
  if (r) return -1;
  ContactOutputSetChild((int)pid, out); /* an interrupted run stops it and removes its file */
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) break;
  ContactOutputSetChild(0, NULL);
  if (guard && tripped && WIFSIGNALED(st) && WTERMSIG(st) != SIGINT && WTERMSIG(st) != SIGTERM) *tripped = PETSC_TRUE;
  if (WIFSIGNALED(st)) return GMSH_SIGNALLED + WTERMSIG(st);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
