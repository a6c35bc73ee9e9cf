/* Options files and errors in option values.

   PETSc reads "-options_file FILE" inside PetscInitialize(), where a missing
   file or a malformed line stops the program with a full traceback and
   MPI_Abort. So the program reads its options files itself, before
   PetscInitialize(), and hands PETSc the expanded command line: each
   "-options_file FILE" is replaced by FILE's options, in place, so that the
   order of precedence is PETSc's (the last setting of an option wins).

   The syntax is PETSc's (PetscOptionsInsertFile): one option per line, "-name"
   or "-name value", a value with spaces in double quotes, "#" starts a comment;
   a line may itself be "-options_file OTHER". YAML files (-options_file_yaml,
   or a name ending in .yaml, .yml, .json or :yaml) are checked for
   readability and left to PETSc. PETSc's "alias" lines are refused.

   A relative path written in an options file is relative to that file's
   folder, so that a scene names its .geo files as "indenter.geo" and runs from
   any directory: the file of every option is kept, and the program's path
   options are resolved with ContactOptionsResolvePath() (nested -options_file
   lines here, while reading).

   An option that takes a value but is given without one (followed by another
   option, or last) is given a spelling of true here (FillMissingValues), so
   that PETSc's conversion of a number or a choice fails and names it, where
   PETSc would read the option as not given (a number) or as empty (a name);
   see options.h.

   This runs before PETSc exists, so it is plain C (malloc, stdio) and reports
   an error as a message for main() to print. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include <petscksp.h>
#include <petsctao.h>
#include "options.h"

#define MAX_DEPTH 16

typedef struct {
  int    n, cap;
  char **s;
} StrList;

/* The expanded command line: argv[0] and the options, each token with its
   source (an index in files, or -1 for the command line). */
typedef struct {
  StrList tok;
  int    *src;
  StrList files;
} Args;

static Args expanded;

static int ListPush(StrList *l, const char *s, size_t n)
{
  char *c;

  if (l->n + 2 > l->cap) {
    int    cap = l->cap ? 2 * l->cap : 64;
    char **s2  = (char **)realloc(l->s, (size_t)cap * sizeof(char *));
    if (!s2) return 1;
    l->s   = s2;
    l->cap = cap;
  }
  if (!(c = (char *)malloc(n + 1))) return 1;
  memcpy(c, s, n);
  c[n]         = 0;
  l->s[l->n++] = c;
  l->s[l->n]   = NULL;
  return 0;
}

static void ListFree(StrList *l)
{
  for (int i = 0; i < l->n; ++i) free(l->s[i]);
  free(l->s);
  l->s = NULL;
  l->n = l->cap = 0;
}

static int ArgsPush(Args *a, const char *s, int src, char err[], size_t len)
{
  int *src2;

  if (ListPush(&a->tok, s, strlen(s)) || !(src2 = (int *)realloc(a->src, (size_t)a->tok.cap * sizeof(int)))) {
    snprintf(err, len, "out of memory reading options");
    return 1;
  }
  a->src                = src2;
  a->src[a->tok.n - 1]  = src;
  return 0;
}

static void ArgsFree(Args *a)
{
  ListFree(&a->tok);
  ListFree(&a->files);
  free(a->src);
  a->src = NULL;
}

/* PetscOptionsValidKey: "-" or "--", then a letter, and not a number ("-inf"). */
static int ValidKey(const char *key)
{
  char *end;

  if (!key || key[0] != '-') return 0;
  if (key[1] == '-') key++;
  if (!isalpha((unsigned char)key[1])) return 0;
  (void)strtod(key, &end);
  if (end != key && !(*end == '_' || isalnum((unsigned char)*end))) return 0;
  return 1;
}

static int EndsWith(const char *s, const char *tail)
{
  size_t ls = strlen(s), lt = strlen(tail);
  return ls >= lt && !strcmp(s + ls - lt, tail);
}

static int IsYAMLName(const char *f)
{
  return EndsWith(f, ".yaml") || EndsWith(f, ".yml") || EndsWith(f, ".json") || EndsWith(f, ":yaml");
}

/* path relative to the folder of file (file NULL: to the current directory). */
static void JoinFolder(const char *file, const char *path, char out[], size_t len)
{
  const char *slash = file ? strrchr(file, '/') : NULL;

  if (!slash || path[0] == '/' || !path[0]) snprintf(out, len, "%s", path);
  else snprintf(out, len, "%.*s/%s", (int)(slash - file), file, path);
}

/* 0 if path is a readable regular file, else a message in err. */
static int CheckReadable(const char *path, const char *what, char err[], size_t len)
{
  struct stat st;
  FILE       *fp;

  if (stat(path, &st)) {
    snprintf(err, len, "cannot read %s %s: %s", what, path, strerror(errno));
    return 1;
  }
  if (S_ISDIR(st.st_mode)) {
    snprintf(err, len, "%s %s is a directory", what, path);
    return 1;
  }
  if (!(fp = fopen(path, "r"))) {
    snprintf(err, len, "cannot read %s %s: %s", what, path, strerror(errno));
    return 1;
  }
  fclose(fp);
  return 0;
}

/* A YAML options file is PETSc's to read; only its existence is checked here. */
static int PassYAML(Args *out, const char *key, const char *file, int src, char err[], size_t len)
{
  char path[4096];

  snprintf(path, sizeof(path), "%s", file);
  if (EndsWith(path, ":yaml")) path[strlen(path) - 5] = 0;
  if (CheckReadable(path, "options file", err, len)) return 1;
  return ArgsPush(out, key, src, err, len) || ArgsPush(out, file, src, err, len);
}

static int ExpandFile(Args *out, const char *file, int depth, char err[], size_t len);

/* Splits a line as PetscToken does with ' ': a token that starts with '"'
   ends at the next '"'. */
static int Tokenize(char *line, char *tok[], int max)
{
  int   n = 0;
  char *p = line;

  while (n < max) {
    char *start, *end;
    while (*p == ' ') p++;
    if (!*p) break;
    if (*p == '"') {
      start = ++p;
      end   = strchr(p, '"');
      if (!end) end = p + strlen(p);
    } else {
      start = p;
      end   = p + strcspn(p, " ");
    }
    p        = *end ? end + 1 : end;
    *end     = 0;
    tok[n++] = start;
  }
  return n;
}

/* A line of options file number src (out->files). */
static int ExpandLine(Args *out, char *line, int src, long lineno, int depth, char err[], size_t len)
{
  const char *file = out->files.s[src];
  char       *tok[3];
  int         n;

  for (char *c = line; *c; ++c) {
    if (*c == '#') {
      *c = 0;
      break;
    }
    if (*c == '\t' || *c == '\r' || *c == '\n') *c = ' ';
  }
  n = Tokenize(line, tok, 3);
  if (!n) return 0;
  if (!strcasecmp(tok[0], "alias")) {
    snprintf(err, len, "options file %s line %ld: 'alias' lines are not supported", file, lineno);
    return 1;
  }
  if (!ValidKey(tok[0])) {
    snprintf(err, len, "options file %s line %ld: '%s' is not an option (an option starts with - and a letter)", file, lineno, tok[0]);
    return 1;
  }
  if (n > 1 && ValidKey(tok[1])) {
    snprintf(err, len, "options file %s line %ld: two options on one line (%s %s)", file, lineno, tok[0], tok[1]);
    return 1;
  }
  if (n > 2) {
    snprintf(err, len, "options file %s line %ld: extra word '%s' after %s %s (one option per line; quote a value with spaces)", file, lineno, tok[2], tok[0], tok[1]);
    return 1;
  }
  if (!strcasecmp(tok[0], "-options_file") || !strcasecmp(tok[0], "-options_file_yaml")) {
    char path[4096], key[64];

    if (n < 2) {
      snprintf(err, len, "options file %s line %ld: %s needs a file name", file, lineno, tok[0]);
      return 1;
    }
    /* relative to this file's folder, like every path in an options file */
    JoinFolder(file, tok[1], path, sizeof(path));
    snprintf(key, sizeof(key), "%s", tok[0]);
    if (!strcasecmp(key, "-options_file_yaml") || IsYAMLName(path) ? PassYAML(out, key, path, src, err, len) : ExpandFile(out, path, depth + 1, err, len)) {
      const size_t l = strlen(err);
      if (!strstr(err, " line ")) snprintf(err + l, len - l, " (%s %s in %s line %ld)", key, tok[1], out->files.s[src], lineno);
      return 1;
    }
    return 0;
  }
  return ArgsPush(out, tok[0], src, err, len) || (n > 1 && ArgsPush(out, tok[1], src, err, len));
}

static int ExpandFile(Args *out, const char *file, int depth, char err[], size_t len)
{
  FILE  *fp;
  char  *line   = NULL;
  size_t cap    = 0;
  long   lineno = 0;
  int    rc = 0, src;

  if (depth > MAX_DEPTH) {
    snprintf(err, len, "options file %s: options files nested more than %d deep (does one include itself?)", file, MAX_DEPTH);
    return 1;
  }
  if (CheckReadable(file, "options file", err, len)) return 1;
  if (!(fp = fopen(file, "r"))) {
    snprintf(err, len, "cannot read options file %s: %s", file, strerror(errno));
    return 1;
  }
  if (ListPush(&out->files, file, strlen(file))) {
    fclose(fp);
    snprintf(err, len, "out of memory reading options file %s", file);
    return 1;
  }
  src = out->files.n - 1;
  while (!rc && getline(&line, &cap, fp) >= 0) rc = ExpandLine(out, line, src, ++lineno, depth, err, len);
  if (!rc && ferror(fp)) {
    snprintf(err, len, "cannot read options file %s: %s", file, strerror(errno));
    rc = 1;
  }
  free(line);
  fclose(fp);
  return rc;
}

/* The command line (args[1..]) with its options files expanded, as PETSc's
   PetscOptionsInsertArgs() would insert it. */
static int ExpandArgs(Args *out, int argc, char **argv, char err[], size_t len)
{
  if (ArgsPush(out, argv[0], -1, err, len)) return 1;
  for (int i = 1; i < argc; ++i) {
    const int file = ValidKey(argv[i]) && !strcasecmp(argv[i], "-options_file");
    const int yaml = ValidKey(argv[i]) && !strcasecmp(argv[i], "-options_file_yaml");

    if (file || yaml) {
      if (i + 1 >= argc || argv[i + 1][0] == '-') {
        snprintf(err, len, "option %s needs a file name", argv[i]);
        return 1;
      }
      if (yaml || IsYAMLName(argv[i + 1])) {
        if (PassYAML(out, argv[i], argv[i + 1], -1, err, len)) return 1;
      } else if (ExpandFile(out, argv[i + 1], 1, err, len)) return 1;
      ++i;
    } else if (ArgsPush(out, argv[i], -1, err, len)) return 1;
  }
  return 0;
}

/* NUL-separated strings of a list, and back. */
static char *Pack(const StrList *l, int *bytes)
{
  size_t n = 1, off = 0;
  char  *b;

  for (int i = 0; i < l->n; ++i) n += strlen(l->s[i]) + 1;
  if (!(b = (char *)malloc(n))) return NULL;
  for (int i = 0; i < l->n; ++i) {
    size_t m = strlen(l->s[i]) + 1;
    memcpy(b + off, l->s[i], m);
    off += m;
  }
  *bytes = (int)off;
  return b;
}

static int Unpack(StrList *l, const char *b, int bytes)
{
  for (int off = 0; off < bytes;) {
    size_t n = strlen(b + off);
    if (ListPush(l, b + off, n)) return 1;
    off += (int)n + 1;
  }
  return 0;
}

/* PETSc's options whose value may be left out, meaning something of their
   own: viewers and monitors (-tao_view, -ksp_monitor [file], -log_view
   [:file]), -help [intro], -info [file], the debugger's and the memory
   checker's, -prefix_pop. Given alone, they are left alone. */
static int ValueOptional(const char *key)
{
  const char *const within[] = {"view", "monitor", "converged_reason", "draw", "debugger", "malloc", "history"};
  const char *const start[]  = {"help", "h", "info", "log", "prefix_pop", "version", "options_"};
  const char       *name     = key + (key[1] == '-' ? 2 : 1);

  for (size_t i = 0; i < sizeof(within) / sizeof(within[0]); ++i)
    if (strstr(name, within[i])) return 1;
  for (size_t i = 0; i < sizeof(start) / sizeof(start[0]); ++i) {
    const size_t n = strlen(start[i]);
    if (!strncasecmp(name, start[i], n) && (!name[n] || name[n] == '_' || start[i][n - 1] == '_')) return 1;
  }
  return 0;
}

/* The k-th spelling of true that PETSc's PetscOptionsStringToBool() takes
   (case-insensitive "true", "yes", "on": 28 spellings), each option given
   without a value its own, so that a failed conversion names its option.
   Past 28 options given alone the spellings repeat, and such an error may
   name an earlier one; past MAX_MISSING, the last record is reused. */
static void Sentinel(int k, char out[8])
{
  const char *const words[] = {"true", "yes", "on"};

  k %= 28;
  for (int w = 0; w < 3; ++w) {
    const int n = (int)strlen(words[w]);
    if (k < (1 << n)) {
      for (int c = 0; c <= n; ++c) out[c] = (char)(c < n && (k >> c & 1) ? toupper((unsigned char)words[w][c]) : words[w][c]);
      return;
    }
    k -= 1 << n;
  }
}

#define MAX_MISSING 64
typedef struct {
  char name[128], value[8], next[128];
  int  src;
} Missing;
static Missing missing[MAX_MISSING];
static int     nmissing;

/* Every option given without a value (followed by another option, or last)
   gets one: a spelling of true (Sentinel), what PETSc makes of a switch given
   alone, so that a switch reads as before, while a number or a choice fails
   PETSc's conversion (reported by ContactOptionsDescribeValueError) and a
   name or path of the program's fails ContactOptionsString(). Options whose
   value is optional (ValueOptional) are left alone. The same on every rank. */
static int FillMissingValues(Args *a)
{
  Args b = {{0, 0, NULL}, NULL, a->files};
  char err[64];

  for (int i = 0; i < a->tok.n; ++i) {
    const char *t = a->tok.s[i], *next = i + 1 < a->tok.n ? a->tok.s[i + 1] : NULL;
    if (ArgsPush(&b, t, a->src[i], err, sizeof(err))) return 1;
    if (i && ValidKey(t) && (!next || ValidKey(next)) && !ValueOptional(t)) {
      Missing *m = &missing[nmissing < MAX_MISSING ? nmissing : MAX_MISSING - 1];
      snprintf(m->name, sizeof(m->name), "%s", t);
      snprintf(m->next, sizeof(m->next), "%s", next ? next : "");
      Sentinel(nmissing, m->value);
      m->src = a->src[i];
      if (nmissing < MAX_MISSING) nmissing++;
      if (ArgsPush(&b, m->value, a->src[i], err, sizeof(err))) return 1;
    }
  }
  ListFree(&a->tok);
  free(a->src);
  a->tok = b.tok;
  a->src = b.src;
  return 0;
}

/* The option given without the value `value` (a sentinel), or NULL. */
static const Missing *FindMissing(const char *value)
{
  for (int i = 0; value && i < nmissing; ++i)
    if (!strcmp(missing[i].value, value)) return &missing[i];
  return NULL;
}

/* "option -x needs <what>, none given (where)" */
static void SayMissing(const Missing *m, const char what[], char buf[], size_t len)
{
  char where[PETSC_MAX_PATH_LEN + 160];

  if (m->src >= 0) snprintf(where, sizeof(where), "in options file %s", expanded.files.s[m->src]);
  else if (m->next[0]) snprintf(where, sizeof(where), "on the command line, followed by %s", m->next);
  else snprintf(where, sizeof(where), "last on the command line");
  snprintf(buf, len, "option %s needs %s, none given (%s)", m->name, what, where);
}

PetscBool ContactOptionsGivenWithoutValue(const char value[])
{
  return FindMissing(value) ? PETSC_TRUE : PETSC_FALSE;
}

int ContactOptionsExpandFiles(MPI_Comm comm, int *argc, char ***argv, char err[], size_t len)
{
  int   rank, info[4] = {0, 0, 0, 0}; /* error, tokens, bytes of the packed tokens, of the packed files */
  char *ptok = NULL, *pfiles = NULL;
  Args  a = {{0, 0, NULL}, NULL, {0, 0, NULL}};

  err[0] = 0;
  (void)MPI_Comm_rank(comm, &rank);
  if (!rank) {
    if (ExpandArgs(&a, *argc, *argv, err, len)) info[0] = 1;
    else if (!(ptok = Pack(&a.tok, &info[2])) || !(pfiles = Pack(&a.files, &info[3]))) {
      snprintf(err, len, "out of memory reading options");
      info[0] = 1;
    }
    info[1] = a.tok.n;
  }
  (void)MPI_Bcast(info, 4, MPI_INT, 0, comm);
  if (!info[0] && rank) {
    ptok   = (char *)malloc((size_t)info[2] + 1);
    pfiles = (char *)malloc((size_t)info[3] + 1);
    a.src  = (int *)malloc(((size_t)info[1] + 1) * sizeof(int));
    if (!ptok || !pfiles || !a.src) info[0] = 2; /* this rank alone: reported below */
  }
  if (info[0] == 1) (void)MPI_Bcast(err, (int)len, MPI_CHAR, 0, comm);
  else if (!info[0]) {
    (void)MPI_Bcast(ptok, info[2], MPI_CHAR, 0, comm);
    (void)MPI_Bcast(pfiles, info[3], MPI_CHAR, 0, comm);
    (void)MPI_Bcast(a.src, info[1], MPI_INT, 0, comm);
    expanded.src = a.src;
    a.src        = NULL;
    if (Unpack(&expanded.tok, ptok, info[2]) || Unpack(&expanded.files, pfiles, info[3])) info[0] = 2;
  }
  if (!info[0] && FillMissingValues(&expanded)) info[0] = 2;
  if (info[0] == 2) snprintf(err, len, "out of memory reading options");
  free(ptok);
  free(pfiles);
  ArgsFree(&a);
  if (info[0]) return 1;
  *argc = expanded.tok.n;
  *argv = expanded.tok.s;
  return 0;
}

int ContactOptionsPeek(int argc, char **argv, const char name[], char value[], size_t len)
{
  Args a     = {{0, 0, NULL}, NULL, {0, 0, NULL}};
  char err[256];
  int  found = 0;

  value[0] = 0;
  if (!ExpandArgs(&a, argc, argv, err, sizeof(err))) {
    for (int i = 1; i < a.tok.n; ++i) {
      if (strcasecmp(a.tok.s[i], name)) continue;
      found = 1;
      if (i + 1 < a.tok.n && a.tok.s[i + 1][0] != '-') snprintf(value, len, "%s", a.tok.s[i + 1]);
      else value[0] = 0;
    }
  }
  ArgsFree(&a);
  return found;
}

void ContactOptionsFinalize(void)
{
  ArgsFree(&expanded);
}

PetscErrorCode ContactOptionsResolvePath(const char pre[], const char opt[], char path[], size_t len, char where[], size_t wlen)
{
  char prefix[512] = "", name[512];
  int  stack[32], depth = 0, src = -2; /* -2: not on the expanded command line */

  PetscFunctionBeginUser;
  if (where) where[0] = 0;
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s%s", pre ? pre : "", opt + 1));
  /* the last setting wins, as PETSc inserts them; -prefix_push applies to the names after it */
  for (int i = 1; i < expanded.tok.n; ++i) {
    const char *t = expanded.tok.s[i];

    if (!ValidKey(t)) continue;
    if (!strcasecmp(t, "-prefix_push") && i + 1 < expanded.tok.n) {
      if (depth < 32) stack[depth++] = (int)strlen(prefix);
      PetscCall(PetscStrlcat(prefix, expanded.tok.s[++i], sizeof(prefix)));
    } else if (!strcasecmp(t, "-prefix_pop")) {
      if (depth) prefix[stack[--depth]] = 0;
    } else if (!strcasecmp(t, "-options_file") || !strcasecmp(t, "-options_file_yaml")) {
      ++i;
    } else {
      char full[1024];
      PetscCall(PetscSNPrintf(full, sizeof(full), "%s%s", prefix, t + 1));
      if (!strcasecmp(full, name)) src = expanded.src[i];
    }
  }
  if (src == -2 || !path[0] || path[0] == '/') PetscFunctionReturn(0);
  if (src >= 0) {
    char        given[PETSC_MAX_PATH_LEN];
    const char *file = expanded.files.s[src];
    PetscCall(PetscStrncpy(given, path, sizeof(given)));
    JoinFolder(file, given, path, len);
    if (where) PetscCall(PetscSNPrintf(where, wlen, "%s in %s, relative to that file's folder", given, file));
  } else if (where) {
    char cwd[PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(where, wlen, "relative to the current directory %s", getcwd(cwd, sizeof(cwd)) ? cwd : "."));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOptionsGetInputFile(MPI_Comm comm, const char pre[], const char opt[], char path[], size_t len)
{
  char        where[2 * PETSC_MAX_PATH_LEN + 64], err[3 * PETSC_MAX_PATH_LEN + 256] = "";
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(ContactOptionsResolvePath(pre, opt, path, len, where, sizeof(where)));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    struct stat st;
    FILE       *fp = NULL;
    const char *why = NULL;

    if (stat(path, &st)) why = strerror(errno);
    else if (S_ISDIR(st.st_mode)) why = "it is a directory";
    else if (!(fp = fopen(path, "r"))) why = strerror(errno);
    if (fp) fclose(fp);
    if (why) PetscCall(PetscSNPrintf(err, sizeof(err), "option -%s%s: cannot read %s%s%s%s: %s", pre ? pre : "", opt + 1, path, where[0] ? " (" : "", where, where[0] ? ")" : "", why));
  }
  PetscCallMPI(MPI_Bcast(err, sizeof(err), MPI_CHAR, 0, comm));
  PetscCheck(!err[0], comm, PETSC_ERR_FILE_OPEN, "%s", err);
  PetscFunctionReturn(0);
}

/* The value quoted by PETSc's message, and what it should have been. */
/* The known names of a PETSc type family, as "a, b, c" (the types PETSc
   registers once a solver of that family exists). */
static void KnownTypes(const char kind[], char buf[], size_t len)
{
  PetscFunctionList list = NULL;
  const char      **names;
  int               n = 0;

  buf[0] = 0;
  if (!strcmp(kind, "KSP")) list = KSPList;
  else if (!strcmp(kind, "PC")) list = PCList;
  else if (!strcmp(kind, "Tao")) list = TaoList;
  else if (!strcmp(kind, "TaoLineSearch")) list = TaoLineSearchList;
  if (!list || PetscFunctionListGet(list, &names, &n)) return;
  for (int i = 0; i < n && names[i]; ++i) /* PETSc 3.18 counts the NULL that ends the array */
    if (strlen(buf) + strlen(names[i]) + 3 < len) {
      if (i) strcat(buf, ", ");
      strcat(buf, names[i]);
    }
  (void)PetscFree(names);
}

/* PETSc's message of a value its options code cannot take: the value, and
   what was expected (a number, an integer, a boolean, or a known type of a
   family, with the known ones). */
static PetscBool ParseValueError(const char fun[], const char mess[], char value[], size_t len, char expected[], size_t elen)
{
  const char *v = NULL, *end = NULL, *const unknown = "Unable to find requested ";

  if (!fun || !mess) return PETSC_FALSE;
  if (!strncmp(mess, unknown, strlen(unknown)) && strstr(mess, " type ")) { /* XSetType() with an unknown name */
    const char *kind = mess + strlen(unknown), *t = strstr(kind, " type ");
    char        k[64], known[1024];
    if ((size_t)(t - kind) >= sizeof(k)) return PETSC_FALSE;
    memcpy(k, kind, (size_t)(t - kind));
    k[t - kind] = 0;
    KnownTypes(k, known, sizeof(known));
    snprintf(expected, elen, "a known %s type%s%s%s", k, known[0] ? " (" : "", known, known[0] ? ")" : "");
    v   = t + 6;
    end = v + strlen(v);
  } else {
    if (!strcmp(fun, "PetscOptionsStringToReal") || !strcmp(fun, "PetscOptionsStringToScalar")) snprintf(expected, elen, "a number");
    else if (!strcmp(fun, "PetscOptionsStringToInt")) snprintf(expected, elen, "an integer");
    else if (!strcmp(fun, "PetscOptionsStringToBool")) snprintf(expected, elen, "true or false");
    else return PETSC_FALSE;
    if (!strncmp(mess, "Input string ", 13)) {
      v   = mess + 13;
      end = strstr(v, " has no ");
    } else if (!strncmp(mess, "Unknown logical value: ", 23)) {
      v   = mess + 23;
      end = v + strlen(v);
    } else if (strstr(mess, "length zero")) {
      v = end = mess; /* the empty string */
    }
  }
  if (!v || !end || (size_t)(end - v) >= len) return PETSC_FALSE;
  memcpy(value, v, (size_t)(end - v));
  value[end - v] = 0;
  return PETSC_TRUE;
}

/* 1 if value is v or one of its comma-separated entries (array options). */
static int HasEntry(const char *v, const char *value)
{
  const size_t n = strlen(value);

  if (!strcmp(v, value)) return 1;
  for (const char *p = v;;) {
    const char  *q = strchr(p, ',');
    const size_t m = q ? (size_t)(q - p) : strlen(p);
    if (m == n && !strncmp(p, value, n)) return 1;
    if (!q) return 0;
    p = q + 1;
  }
}

/* PetscOptionsGetEList()'s message of an enumerated option given without its
   value, "Unknown option V for -NAME. Available options: A B C" (V a
   sentinel), as "option -NAME needs one of A, B, C, none given (...)". */
static PetscBool DescribeMissingChoice(const char mess[], char buf[], size_t len)
{
  const char *v = mess + 15, *end = strstr(v, " for -"), *avail = strstr(mess, "Available options: ");
  char        value[16], expected[1200], *c;

  if (!end || (size_t)(end - v) >= sizeof(value)) return PETSC_FALSE;
  memcpy(value, v, (size_t)(end - v));
  value[end - v] = 0;
  if (!FindMissing(value)) return PETSC_FALSE;
  snprintf(expected, sizeof(expected), "one of %s", avail ? avail + 19 : "its choices");
  for (size_t l = strlen(expected); l && expected[l - 1] == ' ';) expected[--l] = 0;
  for (c = strchr(expected + 7, ' '); c && strlen(expected) + 2 < sizeof(expected); c = strchr(c + 2, ' ')) { /* "a b c" as "a, b, c" */
    memmove(c + 1, c, strlen(c) + 1);
    *c = ',';
  }
  SayMissing(FindMissing(value), expected, buf, len);
  return PETSC_TRUE;
}

PetscBool ContactOptionsDescribeValueError(const char fun[], const char mess[], char buf[], size_t len)
{
  char        value[256], names[512] = "", *all = NULL, *tok, *save = NULL, expected[1200];
  const char *name = NULL, *val = NULL;
  int         found = 0;

  if (mess && !strncmp(mess, "Unknown option ", 15)) return DescribeMissingChoice(mess, buf, len);
  if (!ParseValueError(fun, mess, value, sizeof(value), expected, sizeof(expected))) return PETSC_FALSE;
  if (FindMissing(value)) { /* an option given without its value */
    SayMissing(FindMissing(value), expected, buf, len);
    return PETSC_TRUE;
  }
  /* the database as "-name value -name value ..."; the option being converted
     has just been looked up, so it is marked used */
  if (PetscOptionsGetAll(NULL, &all) || !all) return PETSC_FALSE;
  for (tok = strtok_r(all, " ", &save);; tok = strtok_r(NULL, " ", &save)) {
    if (!tok || ValidKey(tok)) {
      if (name) {
        PetscBool used = PETSC_FALSE;
        if (!PetscOptionsUsed(NULL, name + 1, &used) && used && HasEntry(val ? val : "", value) && strlen(names) + strlen(name) + 8 < sizeof(names)) {
          if (found++) strcat(names, " or ");
          strcat(names, name);
        }
      }
      if (!tok) break;
      name = tok;
      val  = NULL;
    } else val = tok; /* a value with spaces is seen by its last word */
  }
  (void)PetscFree(all);
  if (!found) return PETSC_FALSE;
  snprintf(buf, len, "option %s: '%s' is not %s", names, value, expected);
  return PETSC_TRUE;
}

PetscErrorCode ContactOptionsRealNoDefault(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char deflt[], PetscBool has, PetscReal *value, PetscBool *set)
{
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetReal(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, value, &flg));
  if (PetscOptionsObject->printhelp && PetscOptionsObject->count == 1 && !PetscOptionsObject->alreadyprinted) {
    const char *pre = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
    if (flg || has) PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "  -%s%s <%g : %s>: %s\n", pre, opt + 1, (double)*value, deflt, text));
    else PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "  -%s%s <%s>: %s\n", pre, opt + 1, deflt, text));
  }
  if (set) *set = flg;
  PetscFunctionReturn(0);
}

/* The program's names, paths and lists: given without a value they hold a
   sentinel (FillMissingValues), which no check of a name would catch. */
static PetscErrorCode CheckGiven(PetscOptionItems *PetscOptionsObject, const char opt[])
{
  const char *value;
  PetscBool   flg;
  char        msg[PETSC_MAX_PATH_LEN + 512] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, &value, &flg));
  if (flg && FindMissing(value)) SayMissing(FindMissing(value), "a value", msg, sizeof(msg));
  PetscCheck(!msg[0], PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "%s", msg);
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOptionsString(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char man[], const char current[], char value[], size_t len, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString_Private(PetscOptionsObject, opt, text, man, current, value, len, set));
  PetscCall(CheckGiven(PetscOptionsObject, opt));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOptionsStringArray(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char man[], char *value[], PetscInt *n, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckGiven(PetscOptionsObject, opt)); /* before: the array would hold the sentinel, for the caller to free */
  PetscCall(PetscOptionsStringArray_Private(PetscOptionsObject, opt, text, man, value, n, set));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOptionsFList(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char man[], PetscFunctionList list, const char current[], char value[], size_t len, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFList_Private(PetscOptionsObject, opt, text, man, list, current, value, len, set));
  PetscCall(CheckGiven(PetscOptionsObject, opt));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactOptionsListNames(PetscFunctionList list, char known[], size_t len)
{
  const char **names;
  int          n;

  PetscFunctionBeginUser;
  known[0] = 0;
  PetscCall(PetscFunctionListGet(list, &names, &n));
  for (int i = 0; i < n; ++i) {
    if (!names[i] || !names[i][0]) continue;
    PetscCall(PetscStrlcat(known, known[0] ? ", " : "", len));
    PetscCall(PetscStrlcat(known, names[i], len));
  }
  PetscCall(PetscFree(names));
  PetscFunctionReturn(0);
}

PetscErrorCode ContactGradientToleranceGiven(PetscBool *given)
{
  const char *const tols[] = {"-tao_gatol", "-tao_grtol", "-tao_gttol"};

  PetscFunctionBeginUser;
  *given = PETSC_FALSE;
  for (size_t i = 0; i < sizeof(tols) / sizeof(tols[0]); ++i) {
    PetscBool flg;
    PetscCall(PetscOptionsHasName(NULL, NULL, tols[i], &flg));
    *given = (PetscBool)(*given || flg);
  }
  PetscFunctionReturn(0);
}
