#pragma once
#include <petscsys.h>

#define GMSH_SIGNALLED 128 /* as a shell reports a child a signal killed */

/* What a guarded run of Gmsh may take: CPU seconds and address space (bytes);
   0: no limit on that one. */
typedef struct {
  int    cpuSeconds;
  double memoryBytes;
} GmshGuard;

/* Runs argv[0] (looked up in PATH) with stdout and stderr into log and waits
   for it: its exit status, -1 if it could not be run, or GMSH_SIGNALLED plus
   the signal's number if a signal killed it (a crash, a tripped guard). With a
   guard, the run is held to its limits (and writes no core file); *tripped
   says whether it was stopped there. out: the file it writes, removed if
   the program is interrupted meanwhile. */
int GmshRun(char *const argv[], const char log[], const char out[], const GmshGuard *guard, PetscBool *tripped);
