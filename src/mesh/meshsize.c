/* The size check's estimate: about how many nodes Gmsh will make of a .geo,
   asked of Gmsh itself before the mesh is made, so that a mesh that would not
   fit is refused in seconds, and a graded mesh is not refused for the size of
   its finest part.

   Probe. Gmsh's -clscale s multiplies every mesh size (the points', size
   fields', background fields') by s, so a mesh whose sizes all come from
   them has N(s) ~ N(1) / s^2 nodes once it resolves the geometry. Measured on
   ball.geo at h = 0.00125 (N(1) = 96,885 nodes): N(s) s^2 / N(1) = 1.016,
   1.044, 1.068 at s = 2, 4, 8 (N(s) = 24,600, 6,321, 1,617 nodes), 0.82 at
   s = 16 (309 nodes: the grading no longer resolved). The boundary's nodes go
   as 1/s, so the scaled count is a little high, the safe side. A probe is
   Gmsh's own mesh (the .geo's element order) at the s that should give about
   PROBE_NODES nodes, its count times s^2; one of PROBE_NODES / 4 or more
   (about 7 % high at most, measured) is taken, with two second opinions at
   s sqrt(2) and s / sqrt(2), the largest of the three kept: a full-quad
   recombination can miss its size field at a coarse s (the graded block at
   s = 2 and 4: 0.63 and 0.11 of its count). The first guess of a coarsening
   mesh's s comes from its curves: SURFACE_PER_CURVE times their count squared.

   The first s. The geometry's extent gives E = 4.5 second-order nodes per
   h^2 of its points' bounding box (measured 4.5 to 4.8 on the scenes'
   uniform Tri6 and Quad9 meshes): about right for a uniform mesh, far above
   a graded one whose h is its finest size, below one that the .geo refines
   under h by its own parameters. The first probe is at s0 = sqrt(E /
   PROBE_NODES); each next one at s sqrt(N(s) / PROBE_NODES), never below 1,
   nor below s / 16 in one step (the first probe of a graded mesh is coarse
   and below the asymptote). A probe at s = 1 is the mesh itself: its count is
   exact, and the mesh is kept as the cached one, so a small mesh costs no
   second run.

   Structured meshes. A transfinite curve keeps its node count whatever s is,
   so a structured mesh does not coarsen and a probe would be the whole mesh,
   not 1/s^2 of it. The curves alone (gmsh -1, cheap) are meshed at s0 / 4
   (at least 2), then each half of the last: a coarsening curve's nodes about double from one to
   the next (measured 1.9 to 2.1 from s = 64 to 1 on ball, flat, the hertz
   indenter and the graded block, once each curve has more than one
   element), a structured block's stay at 1,200. Where they grow by half,
   the mesh coarsens; where they do not, with CURVE_NODES or more nodes
   already (a coarse scale leaves each curve one element, whatever it is),
   or down to s = 1, it does not, and it is probed at s = 1.

   Guard. A .geo that refines below h by its own parameters (a size field
   with its own minimum), or a structured mesh, can make a probe as large as
   a mesh that does not fit: every probe runs under a limit of PROBE_SECONDS
   of CPU and PROBE_BYTES of address space (gmshrun.c). A tripped probe is
   retried at 4 s (16 times fewer nodes where the mesh coarsens); where the
   mesh does not coarsen, or after PROBE_RUNS runs, the extent E is the
   estimate, as before probes. A probe that Gmsh fails at s > 1 is retried
   at 0.8 s: a full-quad recombination (RecombinationAlgorithm 2 or 3) fails
   on a boundary with an odd count of edges ("1D mesh cannot be divided by
   2"), as sphere's flat.geo does at s = 3, 4 and 9.5 at h = 0.005 and not
   at 1, 2 or 6; one that fails at s = 1 (a .geo Gmsh cannot mesh) leaves E:
   the real run then reports Gmsh's error. */
#include <unistd.h>
#include <math.h>
#include "meshsize.h"
#include "gmshrun.h"

#define PROBE_NODES   8000.0 /* nodes a probe aims at: about 0.3 s of Gmsh (Tri6) */
#define PROBE_SECONDS 2      /* CPU a probe may take: Gmsh makes 3.6e4 (Tri6) to 1.5e5 (structured Quad9) nodes a second here */
#define PROBE_BYTES   1e9    /* address space a probe may take: Gmsh starts at 0.12 GB, and takes 0.35 kB a node */
#define PROBE_FLOOR   5e4    /* nodes a tripped probe had at least: PROBE_SECONDS at the slowest rate measured, less a third */
#define PROBE_RUNS    8      /* 2D probes at the most */
#define SURFACE_PER_CURVE 0.1 /* a surface's nodes over the square of its curves': 0.06 (a square) to 0.3 (measured) */
#define CURVE_NODES   200.0  /* curve nodes past which a count that does not grow under a finer scale is taken as fixed */

/* The mesh of a .geo at dimension dim and size scale s (none if 1), written
   to out: argv's command with those in place. av has room for argv's
   entries and 6 more. */
static void ProbeCommand(char *const argv[], const char geo[], int dim, const char scale[], const char out[], char *av[], size_t max)
{
  static char *const dims[] = {(char *)"-0", (char *)"-1", (char *)"-3"}; /* -3: the same mesh as -2 where the .geo has no volume, the whole mesh where it has */
  size_t             n      = 0;

  for (; argv[n] && n + 7 < max; ++n) av[n] = argv[n];
  av[1] = dims[dim];
  if (scale) {
    av[n++] = (char *)"-clscale";
    av[n++] = (char *)scale;
  }
  av[n++] = (char *)geo;
  av[n++] = (char *)"-o";
  av[n++] = (char *)out;
  av[n]   = NULL;
}

/* The extent estimate E (above), from the geometry's points unrolled by Gmsh
   without meshing (gmsh -0); -1 if the geometry cannot be unrolled. */
static double MeshExtentNodes(char *const argv[], const char geo[], double h, const char out[])
{
  char   line[1024], *av[256];
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  FILE  *fp;
  int    n = 0;

  ProbeCommand(argv, geo, 0, NULL, out, av, sizeof(av) / sizeof(av[0]));
  if (GmshRun(av, "/dev/null", out, NULL, NULL) != 0 || !(fp = fopen(out, "r"))) {
    (void)unlink(out);
    return -1;
  }
  while (fgets(line, sizeof(line), fp)) {
    double x, y;
    if (!strncmp(line, "Point(", 6) && sscanf(strchr(line, '{') ? strchr(line, '{') + 1 : line, "%lf , %lf", &x, &y) == 2) {
      lo[0] = fmin(lo[0], x);
      lo[1] = fmin(lo[1], y);
      hi[0] = fmax(hi[0], x);
      hi[1] = fmax(hi[1], y);
      n++;
    }
  }
  fclose(fp);
  (void)unlink(out);
  if (n < 2) return -1;
  return 4.5 * fmax(hi[0] - lo[0], h) * fmax(hi[1] - lo[1], h) / (h * h);
}

/* Whether a Gmsh element type is a surface's (triangles and quadrangles of
   any order). */
static PetscBool ElementIsSurface(int type)
{
  static const int surface[] = {2, 3, 9, 10, 16, 20, 21, 22, 23, 24, 25, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58};

  for (size_t k = 0; k < sizeof(surface) / sizeof(surface[0]); ++k)
    if (type == surface[k]) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* The nodes and surface elements of a Gmsh file (2.2 or 4.1): 0, or -1 if
   it cannot be read; *solid: it has 3D elements (a 3D body's mesh). */
static int MeshFileCount(const char path[], double *nodes, double *elements, PetscBool *solid)
{
  FILE  *fp = fopen(path, "r");
  char   line[1024];
  double v[4];
  int    got = 0, version = 2;

  *nodes = *elements = 0;
  *solid = PETSC_FALSE;
  if (!fp) return -1;
  while (got < 2 && fgets(line, sizeof(line), fp)) {
    if (!strncmp(line, "$MeshFormat", 11) && fgets(line, sizeof(line), fp)) version = atoi(line);
    else if (!strncmp(line, "$Nodes", 6) && fgets(line, sizeof(line), fp)) {
      int k  = sscanf(line, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]);
      *nodes = version >= 4 && k == 4 ? v[1] : v[0];
      got++;
    } else if (!strncmp(line, "$Elements", 9) && fgets(line, sizeof(line), fp)) {
      long blocks = atol(line);
      if (version >= 4) { /* blocks of "dim tag type count", each followed by its count of lines */
        for (long b = 0; b < blocks && fgets(line, sizeof(line), fp); ++b) {
          int  dim, tag, type;
          long count;
          if (sscanf(line, "%d %d %d %ld", &dim, &tag, &type, &count) != 4) break;
          if (dim == 2) *elements += (double)count;
          if (dim == 3) *solid = PETSC_TRUE;
          for (long e = 0; e < count && fgets(line, sizeof(line), fp); ++e) {}
        }
      } else { /* one element a line, "id type ..." */
        for (long e = 0; e < blocks && fgets(line, sizeof(line), fp); ++e) {
          int id, type;
          if (sscanf(line, "%d %d", &id, &type) == 2 && ElementIsSurface(type)) *elements += 1;
          if (type == 4 || type == 5 || type == 11 || type == 12 || type == 17) *solid = PETSC_TRUE;
        }
      }
      got++;
    }
  }
  fclose(fp);
  return got == 2 && *nodes > 0 ? 0 : -1;
}

/* One probe: Gmsh's mesh of dimension dim at scale s under the guard, its
   nodes and surface elements. Returns 0, 1 if the guard tripped, -1 if Gmsh
   failed or its file cannot be read. out (and log) are removed unless kept,
   where they become msh (and its log). */
static int MeshProbe(char *const argv[], const char geo[], int dim, double s, const char out[], const char log[], const char msh[], PetscBool keep, MeshSize *size, double *nodes, double *elements)
{
  const GmshGuard guard = {PROBE_SECONDS, PROBE_BYTES};
  char            scale[32], mshlog[PETSC_MAX_PATH_LEN + 16], *av[256];
  PetscBool       tripped, solid = PETSC_FALSE;
  PetscLogDouble  t0, t1;
  int             r;

  (void)snprintf(scale, sizeof(scale), "%.4g", s);
  ProbeCommand(argv, geo, dim, s > 1 ? scale : NULL, out, av, sizeof(av) / sizeof(av[0]));
  (void)PetscTime(&t0);
  r = GmshRun(av, log, out, &guard, &tripped);
  if (!r) r = MeshFileCount(out, nodes, elements, &solid);
  else r = tripped ? 1 : -1;
  if (!r && solid && s > 1) { /* a volume's nodes go as 1/s^3: one more s than the 2D ladder's s^2 */
    *nodes *= s;
    *elements *= s;
  }
  (void)PetscTime(&t1);
  size->probes++;
  size->seconds += t1 - t0;
  (void)PetscInfo(NULL, "Size probe of %s (gmsh -%d -clscale %s): %s, %g nodes, %g surface elements, %.2f s\n", geo, dim, scale, r == 1 ? "stopped by its guard" : r ? "failed" : "done", r ? 0.0 : *nodes, r ? 0.0 : *elements, (double)(t1 - t0));
  (void)snprintf(mshlog, sizeof(mshlog), "%s.log", msh);
  if (!r && keep && !rename(out, msh) && !rename(log, mshlog)) {
    size->kept = PETSC_TRUE;
    return 0;
  }
  (void)unlink(out);
  (void)unlink(log);
  return r;
}

/* Whether the curves' meshes coarsen with -clscale (above): their nodes at
   s, s / 2, s / 4, ... (s >= 2) until they grow by half from one scale to
   the next (they coarsen), or stay under that with CURVE_NODES or more, or
   down to s = 1 (they do not). *at and *nodes: the last scale and its
   count. A probe that fails says they coarsen: the 2D probes then find out. */
static PetscBool MeshCoarsens(char *const argv[], const char geo[], double s, const char out[], const char log[], const char msh[], MeshSize *size, double *at, double *nodes)
{
  double last = -1, e;

  *at    = 0;
  *nodes = 0;
  for (s = PetscMax(2.0, s); s >= 1; s /= 2) {
    if (MeshProbe(argv, geo, 1, s, out, log, msh, PETSC_FALSE, size, nodes, &e)) return PETSC_TRUE;
    *at = s;
    if (last > 0 && *nodes >= 1.5 * last) return PETSC_TRUE;
    if (last >= CURVE_NODES) return PETSC_FALSE;
    last = *nodes;
  }
  return PETSC_FALSE;
}

/* The 2D probes (above) from scale s: 0 and the estimate in size, or -1 if
   none was had (every probe tripped or failed). */
static int MeshProbeLadder(char *const argv[], const char geo[], double s, const char out[], const char log[], const char msh[], MeshSize *size)
{
  double nodes = 0, elements = 0, tripped = 0;

  for (int k = 0; k < PROBE_RUNS; ++k) {
    int r = MeshProbe(argv, geo, 2, s, out, log, msh, (PetscBool)(s == 1), size, &nodes, &elements);

    if ((r < 0 && s == 1) || (r == 1 && !size->coarsens)) break; /* Gmsh's own error, or no coarser probe to try */
    if (r < 0) { /* at a coarse scale, a full-quad recombination can fail on an odd count of boundary edges */
      s = PetscMax(1.0, 0.8 * s);
      continue;
    }
    if (r == 1) {
      tripped = s;
      s *= 4;
      continue;
    }
    if (s == 1 || nodes >= PROBE_NODES / 4 || k == PROBE_RUNS - 1 || s <= 2 * tripped) { /* no finer probe that would not trip again */
      double n2, e2;
      size->nodes    = nodes * s * s;
      size->elements = elements * s * s;
      size->scale    = s;
      if (s > 1 && !MeshProbe(argv, geo, 2, s * M_SQRT2, out, log, msh, PETSC_FALSE, size, &n2, &e2) && 2 * s * s * n2 > size->nodes) { /* the second opinion, the larger */
        size->nodes    = 2 * s * s * n2;
        size->elements = 2 * s * s * e2;
        size->scale    = s * M_SQRT2;
      }
      if (s > 1 && (r = MeshProbe(argv, geo, 2, s / M_SQRT2, out, log, msh, PETSC_FALSE, size, &n2, &e2)) == 1) n2 = e2 = PROBE_FLOOR; /* tripped: it had more than that */
      if (s > 1 && r >= 0 && s * s * n2 / 2 > size->nodes) { /* and a finer one: a full-quad recombination can miss the size field at a coarse scale */
        size->nodes    = s * s * n2 / 2;
        size->elements = s * s * e2 / 2;
        size->scale    = s / M_SQRT2;
      }
      return 0;
    }
    s = PetscMax(1.0, PetscMax(PetscMax(s / 16, 2 * tripped), s * sqrt(nodes / PROBE_NODES)));
  }
  return -1;
}

PetscErrorCode MeshEstimateSize(char *const argv[], const char geo[], double h, const char msh[], MeshSize *size)
{
  char   out[PETSC_MAX_PATH_LEN + 32], log[PETSC_MAX_PATH_LEN + 32], unrolled[PETSC_MAX_PATH_LEN + 32];
  double extent, s, at, curve;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(size, sizeof(*size)));
  size->nodes = size->elements = -1;
  size->coarsens = PETSC_TRUE;
  PetscCall(PetscSNPrintf(out, sizeof(out), "%s.size%d.msh", msh, (int)getpid()));
  PetscCall(PetscSNPrintf(log, sizeof(log), "%s.size%d.log", msh, (int)getpid()));
  PetscCall(PetscSNPrintf(unrolled, sizeof(unrolled), "%s.size%d.geo_unrolled", msh, (int)getpid()));
  extent = MeshExtentNodes(argv, geo, h, unrolled);
  s      = extent > PROBE_NODES ? sqrt(extent / PROBE_NODES) : 1.0;
  if (s > 1) {
    size->coarsens = MeshCoarsens(argv, geo, s / 4, out, log, msh, size, &at, &curve);
    if (!size->coarsens) s = 1;
    else if (curve > 0) s = PetscMin(s, PetscMax(1.0, at * curve * sqrt(SURFACE_PER_CURVE / PROBE_NODES)));
  }
  if (MeshProbeLadder(argv, geo, s, out, log, msh, size)) {
    size->nodes    = extent;
    size->elements = extent / 4;
    size->scale    = 0;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode MeshSizeSource(const MeshSize *size, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  if (size->scale == 1) PetscCall(PetscSNPrintf(buf, len, "Gmsh's mesh"));
  else if (size->scale > 1) PetscCall(PetscSNPrintf(buf, len, "Gmsh's mesh at %.3g times the size, scaled", size->scale));
  else PetscCall(PetscSNPrintf(buf, len, "from the geometry's extent%s", size->coarsens ? "" : ": a structured mesh too large to probe"));
  PetscFunctionReturn(0);
}
