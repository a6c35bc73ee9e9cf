/* Mesh generation with Gmsh and the physical names of a Gmsh file. */
#include <sys/stat.h>
#include <unistd.h>
#include <errno.h>
#include <ctype.h>
#include <math.h>
#include "contact.h"
#include "meshgen.h"
#include "outputset.h"
#include "gmshrun.h"
#include "meshsize.h"

/* mkdir -p: creates dir and its parents; returns 0 or the errno of the failure. */
int ContactMakeDirs(const char dir[])
{
  char buf[PETSC_MAX_PATH_LEN];

  if (PetscStrncpy(buf, dir, sizeof(buf))) return ENAMETOOLONG;
  for (char *p = buf + 1; *p; ++p) {
    if (*p != '/') continue;
    *p = 0;
    if (mkdir(buf, 0777) && errno != EEXIST) return errno;
    *p = '/';
  }
  if (mkdir(buf, 0777)) {
    struct stat st;
    if (errno != EEXIST) return errno;
    if (stat(buf, &st)) return errno;
    if (!S_ISDIR(st.st_mode)) return ENOTDIR;
  }
  return 0;
}

/* The shortest decimal form of v that reads back as v ("0.005", not
   "0.0050000000000000001"): for file names and Gmsh's -setnumber. */
static PetscErrorCode FormatShortest(double v, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  for (int prec = 1; prec <= 17; ++prec) {
    PetscCall(PetscSNPrintf(buf, len, "%.*g", prec, v));
    if (strtod(buf, NULL) == v) break;
  }
  PetscFunctionReturn(0);
}

/* Parameters are "name=value" with a finite number; they become -setnumber name value. */
static PetscErrorCode CheckParam(const char geo[], const char p[], char name[], char value[])
{
  const char *eq = strchr(p, '=');
  char       *end;
  double      v;

  PetscFunctionBeginUser;
  PetscCheck(eq && eq != p, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "geometry parameter '%s' for %s is not name=value", p, geo);
  PetscCheck((size_t)(eq - p) < 64, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "geometry parameter name too long in '%s'", p);
  for (const char *c = p; c < eq; ++c) PetscCheck(isalnum((unsigned char)*c) || *c == '_', PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "geometry parameter '%s' for %s: name must be letters, digits or _", p, geo);
  v = strtod(eq + 1, &end);
  PetscCheck(end != eq + 1 && *end == 0 && isfinite(v), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "geometry parameter '%s' for %s: value is not a finite number", p, geo);
  PetscCall(PetscStrncpy(name, p, (size_t)(eq - p) + 1));
  PetscCall(FormatShortest(v, value, 64));
  PetscFunctionReturn(0);
}

/* Whether a .geo file uses the number name (-setnumber name): the identifier,
   outside comments and strings, other than in Exists(name) and "name = ...".
   A file that Includes another is given the benefit of the doubt. */
static PetscBool GeoUsesName(const char geo[], const char name[])
{
  const long len = (long)strlen(name);
  FILE     *fp = fopen(geo, "r");
  char     *text;
  long      n;
  PetscBool uses = PETSC_FALSE;

  if (!fp) return PETSC_TRUE; /* reported elsewhere */
  if (fseek(fp, 0, SEEK_END) || (n = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET) || !(text = (char *)malloc((size_t)n + 1))) {
    fclose(fp);
    return PETSC_TRUE;
  }
  n       = (long)fread(text, 1, (size_t)n, fp);
  text[n] = 0;
  fclose(fp);
  for (long i = 0; i < n && !uses;) {
    if (text[i] == '/' && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
    } else if (text[i] == '/' && text[i + 1] == '*') {
      char *end = strstr(text + i + 2, "*/");
      i         = end ? end - text + 2 : n;
    } else if (text[i] == '"') {
      for (++i; i < n && text[i] != '"'; ++i) if (text[i] == '\\') ++i;
      ++i;
    } else if (isalpha((unsigned char)text[i]) || text[i] == '_') {
      long      j = i, k, b;
      PetscBool assigned, exists;

      while (j < n && (isalnum((unsigned char)text[j]) || text[j] == '_')) ++j;
      if (j - i == 7 && !strncmp(text + i, "Include", 7)) uses = PETSC_TRUE;
      else if (j - i == len && !strncmp(text + i, name, (size_t)len)) {
        for (k = j; k < n && isspace((unsigned char)text[k]); ++k) {}
        for (b = i - 1; b >= 0 && isspace((unsigned char)text[b]); --b) {}
        assigned = (PetscBool)(text[k] == '=' && text[k + 1] != '=');
        exists   = (PetscBool)(b >= 6 && text[b] == '(' && !strncmp(text + b - 6, "Exists", 6));
        if (!assigned && !exists) uses = PETSC_TRUE;
      }
      i = j;
    } else ++i;
  }
  free(text);
  return uses;
}

/* Gmsh's first error in its log (lines "Error   : ..."), in msg (empty if
   none): a parse error reads "'<file>', line N: text", given here as
   "line N: text" (the file named only if it is another one, an Include). A
   first error that names no line (an unterminated string or comment) is
   followed by the first one that does, where the parser stopped. */
static PetscErrorCode GmshLogFirstError(const char log[], const char geo[], char msg[], size_t len)
{
  FILE     *fp;
  char      line[1024];
  PetscBool located = PETSC_FALSE;

  PetscFunctionBeginUser;
  msg[0] = 0;
  if (!(fp = fopen(log, "r"))) PetscFunctionReturn(0);
  while (!located && fgets(line, sizeof(line), fp)) {
    char       *text = line + 5, *end;
    const char *file = NULL;

    if (strncmp(line, "Error", 5)) continue;
    while (*text == ' ') ++text;
    if (*text++ != ':') continue;
    while (*text == ' ') ++text;
    text[strcspn(text, "\r\n")] = 0;
    if (text[0] == '\'' && (end = strchr(text + 1, '\'')) && !strncmp(end, "', line ", 8)) {
      *end    = 0;
      file    = strcmp(text + 1, geo) ? text + 1 : NULL;
      text    = end + 3; /* "line N: ..." */
      located = PETSC_TRUE;
    }
    if (!*text || (msg[0] && !located)) continue;
    if (msg[0]) PetscCall(PetscStrlcat(msg, "; ", len));
    if (file) {
      PetscCall(PetscStrlcat(msg, file, len));
      PetscCall(PetscStrlcat(msg, " ", len));
    }
    PetscCall(PetscStrlcat(msg, text, len));
  }
  fclose(fp);
  PetscFunctionReturn(0);
}

/* What Gmsh's exit r says where its log names no error: not run, killed
   by a signal (named), or its exit status. */
static PetscErrorCode GmshStatusText(int r, char text[], size_t len)
{
  PetscFunctionBeginUser;
  if (r < 0) PetscCall(PetscStrncpy(text, "gmsh could not be run", len));
  else if (r > GMSH_SIGNALLED) PetscCall(PetscSNPrintf(text, len, "Gmsh crashed (signal %d, %s)", r - GMSH_SIGNALLED, strsignal(r - GMSH_SIGNALLED)));
  else PetscCall(PetscSNPrintf(text, len, "no error message (exit status %d)", r));
  PetscFunctionReturn(0);
}

/* Whether Gmsh can read geo with the options of argv[1..argc) (gmsh
   -parse_and_exit: no mesh, no file): if not, errmsg names the file and
   Gmsh's first error. Its log is a temporary beside msh. */
static PetscErrorCode GeoCheckParse(char *argv[], PetscInt argc, const char geo[], const char msh[], char errmsg[], size_t len)
{
  char  log[PETSC_MAX_PATH_LEN + 32], gmsh[1024];
  char *mode = argv[1];
  int   r;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(log, sizeof(log), "%s.parse%d.log", msh, (int)getpid()));
  argv[1]        = (char *)"-parse_and_exit"; /* in place of -3 */
  argv[argc]     = (char *)geo;
  argv[argc + 1] = NULL;
  r              = GmshRun(argv, log, log, NULL, NULL);
  argv[1]        = mode;
  if (r != 0) {
    PetscCall(GmshLogFirstError(log, geo, gmsh, sizeof(gmsh)));
    if (!gmsh[0]) PetscCall(GmshStatusText(r, gmsh, sizeof(gmsh)));
    PetscCall(PetscSNPrintf(errmsg, len, "Gmsh cannot read geometry file %s: %s", geo, gmsh));
  }
  (void)unlink(log);
  PetscFunctionReturn(0);
}

/* A tag of the contents of a file (64-bit FNV-1a), for cached mesh names. */
static int FileTag(const char path[], char tag[], size_t len)
{
  FILE              *fp = fopen(path, "rb");
  unsigned long long hash = 1469598103934665603ULL;
  int                c;

  if (!fp) return errno;
  while ((c = fgetc(fp)) != EOF) hash = (hash ^ (unsigned char)c) * 1099511628211ULL;
  fclose(fp);
  snprintf(tag, len, "%016llx", hash);
  return 0;
}

PetscErrorCode MeshGenerate(MPI_Comm comm, const char body[], const char geo[], PetscReal h, PetscInt nparams, char *params[], const char bgm[], const char dir[], PetscReal *maxDofs, const char limit[], PetscBool estimateOnly, char msh[], size_t len)
{
  PetscMPIInt rank;
  int         err = 0, r;
  char        errmsg[PETSC_MAX_PATH_LEN + 256] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    char        base[PETSC_MAX_PATH_LEN], tag[1024] = "", cmd[4096], tmp[PETSC_MAX_PATH_LEN + 16], log[PETSC_MAX_PATH_LEN + 16], hs[64];
    char        names[16][64], values[16][64], *argv[16 + 2 * 3 * 16], bgmTag[32] = "", unused[64] = "";
    PetscInt    argc = 0;
    const char *slash = strrchr(geo, '/');
    struct stat sg, sm;
    size_t      l;

    PetscCall(PetscLogEventBegin(contactLog.meshGenerate, 0, 0, 0, 0));
    PetscCall(PetscStrncpy(base, slash ? slash + 1 : geo, sizeof(base)));
    PetscCall(PetscStrlen(base, &l));
    if (l > 4 && !strcmp(base + l - 4, ".geo")) base[l - 4] = 0;
    PetscCall(FormatShortest((double)h, hs, sizeof(hs)));
    PetscCall(PetscSNPrintf(cmd, sizeof(cmd), "gmsh -3 -v 2 -format msh22 -setnumber h %s", hs));
    PetscCheck(nparams <= 16, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: at most 16 geometry parameters, got %" PetscInt_FMT, geo, nparams);
    for (const char *a = "gmsh\0-3\0-v\0" "2\0-format\0msh22\0-setnumber\0h\0"; *a; a += strlen(a) + 1) argv[argc++] = (char *)a;
    argv[argc++] = hs;
    PetscCall(PetscSNPrintf(tag, sizeof(tag), "h%s", hs));
    for (PetscInt i = 0; i < nparams; ++i) {
      char name[64], value[64], part[160];

      PetscCall(CheckParam(geo, params[i], name, value));
      for (PetscInt j = 0; j < i; ++j) PetscCheck(strcmp(names[j], name), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "geometry parameter '%s' given twice for %s", name, geo);
      if (!unused[0] && strcmp(name, "h") && !GeoUsesName(geo, name)) PetscCall(PetscStrncpy(unused, name, sizeof(unused)));
      PetscCall(PetscStrncpy(names[i], name, sizeof(names[i])));
      PetscCall(PetscStrncpy(values[i], value, sizeof(values[i])));
      argv[argc++] = (char *)"-setnumber";
      argv[argc++] = names[i];
      argv[argc++] = values[i];
      PetscCall(PetscSNPrintf(part, sizeof(part), " -setnumber %s %s", name, value));
      PetscCall(PetscStrlcat(cmd, part, sizeof(cmd)));
      PetscCall(PetscSNPrintf(part, sizeof(part), "_%s%s", name, value));
      PetscCall(PetscStrlcat(tag, part, sizeof(tag)));
    }
    if (bgm && bgm[0]) { /* a size field: -bgm, and adapt = 1 for a .geo that meshes otherwise (structured) without one */
      char part[PETSC_MAX_PATH_LEN + 64];
      if ((err = FileTag(bgm, bgmTag, sizeof(bgmTag)))) {
        PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "cannot read the size field %s: %s", bgm, strerror(err)));
        err = 1;
      }
      argv[argc++] = (char *)"-bgm";
      argv[argc++] = (char *)bgm;
      PetscCall(PetscSNPrintf(part, sizeof(part), " -bgm %s", bgm));
      PetscCall(PetscStrlcat(cmd, part, sizeof(cmd)));
      if (GeoUsesName(geo, "adapt")) {
        for (const char *a = "-setnumber\0adapt\0" "1\0"; *a; a += strlen(a) + 1) argv[argc++] = (char *)a;
        PetscCall(PetscStrlcat(cmd, " -setnumber adapt 1", sizeof(cmd)));
      }
      PetscCall(PetscSNPrintf(part, sizeof(part), "_field%s", bgmTag));
      PetscCall(PetscStrlcat(tag, part, sizeof(tag)));
    }
    PetscCall(PetscSNPrintf(msh, len, "%s/%s-%s.msh", dir, base, tag));
    PetscCall(PetscSNPrintf(log, sizeof(log), "%s.log", msh));
    if (err) { /* the size field could not be read: errmsg says so */
    } else if ((err = ContactMakeDirs(dir))) {
      PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "cannot create mesh directory %s: %s", dir, strerror(err)));
      err = 1;
    } else if (stat(geo, &sg)) {
      err = 1;
      PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "cannot read geometry file %s: %s", geo, strerror(errno)));
    } else if (unused[0]) { /* a syntax error (an unterminated string or comment) can hide a name from GeoUsesName: Gmsh's own error wins */
      err = 1;
      PetscCall(GeoCheckParse(argv, argc, geo, msh, errmsg, sizeof(errmsg)));
      if (!errmsg[0]) PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "geometry parameter '%s' is never used by %s (misspelled?)", unused, geo));
    } else if (estimateOnly && !GeoUsesName(geo, "h")) PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "contact: warning: %s never uses the mesh size h, so -mesh_size and -<body>_mesh_size do not change its mesh (see docs/scenes.md, Geometry files)\n", geo));
    if (!err && (stat(msh, &sm) || sm.st_mtime < sg.st_mtime)) {
      PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp%d.msh", msh, (int)getpid()));
      PetscCall(PetscStrlcat(cmd, " '", sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, geo, sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, "' -o '", sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, tmp, sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, "' > '", sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, log, sizeof(cmd)));
      PetscCall(PetscStrlcat(cmd, "' 2>&1", sizeof(cmd)));
      PetscCall(PetscInfo(NULL, "Meshing: %s\n", cmd));
      if (estimateOnly && *maxDofs > 0 && !bgmTag[0]) { /* refused before meshing if it would not fit (a size field's mesh: by its caller) */
        MeshSize size;
        char     source[128];
        argv[argc] = NULL;
        PetscCall(MeshEstimateSize(argv, geo, (double)h, msh, &size));
        PetscCall(PetscInfo(NULL, "Size of %s: about %g nodes, %g surface elements (clscale %g), %d Gmsh runs, %.2f s%s\n", geo, size.nodes, size.elements, size.scale, size.probes, size.seconds, size.kept ? ", kept as the mesh" : ""));
        if (size.nodes > 0 && 2.0 * size.nodes > *maxDofs) {
          err = 1;
          PetscCall(MeshSizeSource(&size, source, sizeof(source)));
          PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "body %s: mesh size h = %g for %s would give about %.2g elements, %.3g dofs and %.2g GB (%s), more than the %.3g dofs left of the limit (%s); use a larger -%s_mesh_size", body, (double)h, geo, size.elements, 2.0 * size.nodes, 2.0 * size.nodes * CONTACT_BYTES_PER_DOF / 1e9, source, (double)*maxDofs, limit, body));
          if (size.kept) (void)unlink(msh);
        } else if (size.nodes > 0) *maxDofs -= 2.0 * size.nodes; /* what is left for the other bodies */
      }
    }
    if (!err && !estimateOnly && (stat(msh, &sm) || sm.st_mtime < sg.st_mtime)) {
      argv[argc]     = (char *)geo;
      argv[argc + 1] = (char *)"-o";
      argv[argc + 2] = tmp;
      argv[argc + 3] = NULL;
      if ((r = GmshRun(argv, log, tmp, NULL, NULL)) != 0 || stat(tmp, &sm) || sm.st_size == 0) {
        char gmsh[1024];
        err = 1;
        (void)unlink(tmp);
        PetscCall(GeoCheckParse(argv, argc, geo, msh, errmsg, sizeof(errmsg))); /* a file Gmsh cannot read: that error, and no log left */
        if (errmsg[0]) (void)unlink(log);
        else {
          PetscCall(GmshLogFirstError(log, geo, gmsh, sizeof(gmsh)));
          if (!gmsh[0] && r != 0) { /* else Gmsh exited 0 and wrote no mesh */
            size_t n;
            PetscCall(GmshStatusText(r, gmsh, sizeof(gmsh)));
            n = strlen(gmsh);
            if (r > GMSH_SIGNALLED) PetscCall(PetscSNPrintf(gmsh + n, sizeof(gmsh) - n, "; another -%s_mesh_size or meshing algorithm in the file may pass", body));
          }
          PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "gmsh failed on %s (h = %g)%s%s; see %s", geo, (double)h, gmsh[0] ? ": " : "", gmsh, log));
        }
      } else if (rename(tmp, msh)) {
        err = 1;
        PetscCall(PetscSNPrintf(errmsg, sizeof(errmsg), "cannot rename %s to %s: %s", tmp, msh, strerror(errno)));
      }
    }
    PetscCall(PetscLogEventEnd(contactLog.meshGenerate, 0, 0, 0, 0));
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(errmsg, sizeof(errmsg), MPI_CHAR, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_OPEN, "%s", errmsg);
  PetscCallMPI(MPI_Bcast(msh, (int)len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

/* Gmsh 2.2 and 4.1 both store "$PhysicalNames / n / dim tag \"name\"". */
PetscErrorCode MeshReadPhysicalNames(MPI_Comm comm, const char msh[], PetscInt *n, char ***names, PetscInt **dims, PetscInt **tags)
{
  PetscMPIInt rank;
  int         cnt = 0, err = 0;
  char        buf[CONTACT_MAX_BC * 16 * CONTACT_NAME_LEN];
  int         idata[2 * 128];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(buf, sizeof(buf)));
  if (rank == 0) {
    FILE *fp = fopen(msh, "r");
    char  line[1024];

    if (!fp) err = 1;
    else {
      while (fgets(line, sizeof(line), fp)) {
        if (!strncmp(line, "$PhysicalNames", 14)) {
          if (fscanf(fp, "%d", &cnt) != 1 || cnt < 0 || cnt > 128) { err = 2; break; }
          for (int i = 0; i < cnt; ++i) {
            char name[256];
            if (fscanf(fp, "%d %d \"%255[^\"]\"", &idata[2 * i], &idata[2 * i + 1], name) != 3) { err = 2; break; }
            PetscCall(PetscStrncpy(buf + i * CONTACT_NAME_LEN, name, CONTACT_NAME_LEN));
          }
          break;
        }
        if (!strncmp(line, "$Nodes", 6)) break;
      }
      fclose(fp);
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(err != 1, comm, PETSC_ERR_FILE_OPEN, "cannot open mesh file %s", msh);
  PetscCheck(err != 2, comm, PETSC_ERR_FILE_UNEXPECTED, "mesh file %s: malformed $PhysicalNames section", msh);
  PetscCallMPI(MPI_Bcast(&cnt, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(idata, 2 * cnt, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(buf, cnt * CONTACT_NAME_LEN, MPI_CHAR, 0, comm));
  *n = cnt;
  PetscCall(PetscMalloc1(cnt + 1, names));
  PetscCall(PetscMalloc2(cnt + 1, dims, cnt + 1, tags));
  for (int i = 0; i < cnt; ++i) {
    PetscCall(PetscStrallocpy(buf + i * CONTACT_NAME_LEN, &(*names)[i]));
    (*dims)[i] = idata[2 * i];
    (*tags)[i] = idata[2 * i + 1];
  }
  PetscFunctionReturn(0);
}
