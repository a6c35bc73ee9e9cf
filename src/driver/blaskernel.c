/* The BLAS kernel (blaskernel.h).

   Debian's OpenBLAS is built for every x86-64 kernel family and picks one as
   it loads, from the CPU's vendor, family and model. A CPU newer than the
   library (an Intel Xeon of family 6, model 207, for OpenBLAS 0.3.21) is not
   in its table, and it falls back to its oldest kernels (Prescott, SSE3):
   the reference scene's factorisations then take 1.3 to 1.7 times as long as
   with the AVX-512 kernels the CPU runs (measured in issue 46's report: h =
   0.015, 2.8-3.2 s against 2.28 s on 1 rank, 1.9-2.1 s against 1.15 s on 2).

   The kernels' order, and what each needs of the CPU (GCC's
   __builtin_cpu_supports, which also checks that the OS saves the AVX
   registers):

     rank 1  Prescott (SSE3), Core2 (SSSE3), Penryn (SSE4.1)
     rank 2  Nehalem (SSE4.2)
     rank 3  Sandybridge (AVX)
     rank 4  Haswell, Zen (AVX2, FMA)
     rank 5  SkylakeX (AVX-512 F, CD, BW, DQ, VL), Cooperlake (and AVX-512 BF16)

   The CPU's best is the highest rank whose features it has (SkylakeX,
   Haswell, Sandybridge, Nehalem, Prescott). Where OpenBLAS's choice ranks
   below it, the program starts again on it; a choice of OpenBLAS's that
   ranks as high (Cooperlake or Zen on their CPUs) or that is not in the table
   is kept. The choice is made on every rank alike (the same CPU, the same
   answer), before MPI_Init(), so that execv() replaces a process MPI has not
   met yet. CONTACT_BLAS_KERNEL_SOURCE carries how the kernel was chosen
   across the execv() and stops a second one. */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include "blaskernel.h"
#include "options.h"

#define SOURCE_ENV "CONTACT_BLAS_KERNEL_SOURCE"

typedef struct {
  const char *name;
  int         rank;
  int (*supported)(void);
} Kernel;

static int HasSSE3(void)
{
  return __builtin_cpu_supports("sse3");
}
static int HasSSSE3(void)
{
  return __builtin_cpu_supports("ssse3");
}
static int HasSSE41(void)
{
  return __builtin_cpu_supports("sse4.1");
}
static int HasSSE42(void)
{
  return __builtin_cpu_supports("sse4.2");
}
static int HasAVX(void)
{
  return __builtin_cpu_supports("avx");
}
static int HasAVX2(void)
{
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
static int HasAVX512(void)
{
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
}
static int HasAVX512BF16(void)
{
  return HasAVX512() && __builtin_cpu_supports("avx512bf16");
}

/* best first within a rank: the CPU's best is the first of its rank it runs */
static const Kernel kernels[] = {
  {"SkylakeX",    5, HasAVX512    },
  {"Cooperlake",  5, HasAVX512BF16},
  {"Haswell",     4, HasAVX2      },
  {"Zen",         4, HasAVX2      },
  {"Sandybridge", 3, HasAVX       },
  {"Nehalem",     2, HasSSE42     },
  {"Penryn",      1, HasSSE41     },
  {"Core2",       1, HasSSSE3     },
  {"Prescott",    1, HasSSE3      },
};
#define NKERNELS ((int)(sizeof(kernels) / sizeof(kernels[0])))

static struct {
  char name[64];      /* the kernel in use */
  char source[32];    /* how it was chosen */
  char fallback[64];  /* the kernel loaded before the program started again on this one */
  char requested[64]; /* -blas_kernel as BlasKernelSelect() saw it */
  char error[512];    /* a -blas_kernel that could not be honoured */
} state = {"none", "none", "", "", ""};

static const Kernel *KernelFind(const char name[])
{
  for (int k = 0; k < NKERNELS; ++k)
    if (!strcasecmp(kernels[k].name, name)) return &kernels[k];
  return NULL;
}

static const Kernel *KernelBest(void)
{
  __builtin_cpu_init();
  for (int k = 0; k < NKERNELS; ++k)
    if (kernels[k].supported()) return &kernels[k];
  return NULL;
}

/* OpenBLAS's name for its kernels, NULL if the BLAS is another one */
static const char *LoadedKernel(void)
{
  char *(*corename)(void) = (char *(*)(void))dlsym(RTLD_DEFAULT, "openblas_get_corename");
  return corename ? corename() : NULL;
}

static void Known(char buf[], size_t len)
{
  size_t off = 0;
  buf[0]     = 0;
  for (int k = NKERNELS - 1; k >= 0 && off < len; --k) off += (size_t)snprintf(buf + off, len - off, "%s%s", k < NKERNELS - 1 ? ", " : "", kernels[k].name);
}

/* The kernel wanted (NULL: the one loaded), with its source, or an error */
static const Kernel *Wanted(const char loaded[], int given, const char requested[])
{
  const Kernel *best = KernelBest(), *cur = KernelFind(loaded);

  if (given && strcasecmp(requested, "auto")) {
    const Kernel *k = KernelFind(requested);
    char          known[256];

    snprintf(state.source, sizeof(state.source), "-blas_kernel");
    Known(known, sizeof(known));
    if (!k) snprintf(state.error, sizeof(state.error), "-blas_kernel %s: not a kernel of OpenBLAS's this program knows (auto, %s)", requested, known);
    else if (!k->supported()) snprintf(state.error, sizeof(state.error), "-blas_kernel %s: this CPU cannot run it (it lacks the instructions the kernel needs; the best it runs is %s)", k->name, best ? best->name : "none");
    return state.error[0] || !strcasecmp(k->name, loaded) ? NULL : k;
  }
  if (!given && getenv("OPENBLAS_CORETYPE")) {
    snprintf(state.source, sizeof(state.source), "OPENBLAS_CORETYPE");
    return NULL;
  }
  snprintf(state.source, sizeof(state.source), "OpenBLAS");
  if (!best || !cur || cur->rank >= best->rank) return NULL;
  snprintf(state.source, sizeof(state.source), "cpu");
  return best;
}

void BlasKernelSelect(int argc, char **argv)
{
  const char   *loaded = LoadedKernel(), *carried = getenv(SOURCE_ENV);
  const Kernel *want;
  int           given;

  given = ContactOptionsPeek(argc, argv, "-blas_kernel", state.requested, sizeof(state.requested)) && state.requested[0];
  if (!loaded) {
    snprintf(state.source, sizeof(state.source), "not OpenBLAS");
    if (given && strcasecmp(state.requested, "auto")) snprintf(state.error, sizeof(state.error), "-blas_kernel %s: the BLAS loaded is not OpenBLAS", state.requested);
    return;
  }
  snprintf(state.name, sizeof(state.name), "%s", loaded);
  if (carried) { /* started again: "source:OpenBLAS's own choice" */
    const char *colon = strchr(carried, ':');
    snprintf(state.source, sizeof(state.source), "%.*s", colon ? (int)(colon - carried) : (int)strlen(carried), carried);
    if (colon) snprintf(state.fallback, sizeof(state.fallback), "%s", colon + 1);
    (void)unsetenv(SOURCE_ENV); /* the first start checked -blas_kernel's name before it started this one */
    return;
  }
  want = Wanted(loaded, given, state.requested);
  if (!want) return;
  {
    char carry[128];
    snprintf(carry, sizeof(carry), "%s:%s", state.source, loaded);
    if (setenv("OPENBLAS_CORETYPE", want->name, 1) || setenv(SOURCE_ENV, carry, 1)) return;
    (void)execv("/proc/self/exe", argv);
    /* execv() returned: the run goes on with the kernel loaded, and says so */
    (void)unsetenv(SOURCE_ENV);
    snprintf(state.source, sizeof(state.source), "OpenBLAS");
  }
}

PetscErrorCode BlasKernelSetFromOptions(MPI_Comm comm)
{
  char      value[64] = "auto";
  PetscBool set;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "BLAS options", NULL);
  PetscCall(ContactOptionsString(PetscOptionsObject, "-blas_kernel",
                                 "OpenBLAS kernel (auto: the CPU's best where OpenBLAS falls back below it; a name, e.g. Prescott, Nehalem, Sandybridge, Haswell, SkylakeX: that one). Acts as the program starts: on the command line or in an options file",
                                 NULL, value, value, sizeof(value), &set));
  PetscOptionsEnd();
  PetscCheck(!state.error[0], comm, PETSC_ERR_USER_INPUT, "%s", state.error);
  PetscCheck(!set || !strcasecmp(value, state.requested), comm, PETSC_ERR_USER_INPUT, "-blas_kernel %s: given where the program cannot see it as it starts (PETSC_OPTIONS?); give it on the command line or in an options file", value);
  PetscFunctionReturn(0);
}

const char *BlasKernelName(void)
{
  return state.name;
}

const char *BlasKernelSource(void)
{
  return state.source;
}

const char *BlasKernelFallback(void)
{
  return state.fallback;
}

PetscErrorCode BlasKernelView(MPI_Comm comm)
{
  static const char *said[][2] = {
    {"OpenBLAS",          "OpenBLAS's choice for this CPU"                     },
    {"cpu",               "the CPU's features"                                 },
    {"-blas_kernel",      "-blas_kernel"                                       },
    {"OPENBLAS_CORETYPE", "OPENBLAS_CORETYPE"                                  },
    {"not OpenBLAS",      "the BLAS is not OpenBLAS: its kernels are its own"},
  };
  const char *why = state.source;

  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(said) / sizeof(said[0]); ++k)
    if (!strcmp(said[k][0], state.source)) why = said[k][1];
  if (state.fallback[0]) PetscCall(PetscPrintf(comm, "BLAS: OpenBLAS kernel %s (%s, in place of %s)\n", state.name, why, state.fallback));
  else PetscCall(PetscPrintf(comm, "BLAS: OpenBLAS kernel %s (%s)\n", state.name, why));
  PetscFunctionReturn(0);
}
