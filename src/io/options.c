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

   This runs before PETSc exists, so it is plain C (malloc, stdio) and reports
   an error as a message for main() to print. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include "options.h"

#define MAX_DEPTH 16

typedef struct {
  int    n, cap;
  char **s;
} StrList;

static StrList expanded; /* argv[0] and the expanded options, NUL-terminated array */

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
  c[n]          = 0;
  l->s[l->n++]  = c;
  l->s[l->n]    = NULL;
  return 0;
}

static void ListFree(StrList *l)
{
  for (int i = 0; i < l->n; ++i) free(l->s[i]);
  free(l->s);
  l->s = NULL;
  l->n = l->cap = 0;
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
static int PassYAML(StrList *out, const char *key, const char *file, char err[], size_t len)
{
  char path[4096];

  snprintf(path, sizeof(path), "%s", file);
  if (EndsWith(path, ":yaml")) path[strlen(path) - 5] = 0;
  if (CheckReadable(path, "options file", err, len)) return 1;
  if (ListPush(out, key, strlen(key)) || ListPush(out, file, strlen(file))) {
    snprintf(err, len, "out of memory reading options");
    return 1;
  }
  return 0;
}

static int ExpandFile(StrList *out, const char *file, int depth, char err[], size_t len);

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

static int ExpandLine(StrList *out, char *line, const char *file, long lineno, int depth, char err[], size_t len)
{
  char *tok[3];
  int   n;

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
    if (n < 2) {
      snprintf(err, len, "options file %s line %ld: %s needs a file name", file, lineno, tok[0]);
      return 1;
    }
    if (!strcasecmp(tok[0], "-options_file_yaml") || IsYAMLName(tok[1]) ? PassYAML(out, tok[0], tok[1], err, len) : ExpandFile(out, tok[1], depth + 1, err, len)) {
      const size_t l = strlen(err);
      if (!strstr(err, " line ")) snprintf(err + l, len - l, " (%s in %s line %ld)", tok[0], file, lineno);
      return 1;
    }
    return 0;
  }
  if (ListPush(out, tok[0], strlen(tok[0])) || (n > 1 && ListPush(out, tok[1], strlen(tok[1])))) {
    snprintf(err, len, "out of memory reading options file %s", file);
    return 1;
  }
  return 0;
}

static int ExpandFile(StrList *out, const char *file, int depth, char err[], size_t len)
{
  FILE   *fp;
  char   *line = NULL;
  size_t  cap  = 0;
  long    lineno = 0;
  int     rc   = 0;

  if (depth > MAX_DEPTH) {
    snprintf(err, len, "options file %s: options files nested more than %d deep (does one include itself?)", file, MAX_DEPTH);
    return 1;
  }
  if (CheckReadable(file, "options file", err, len)) return 1;
  if (!(fp = fopen(file, "r"))) {
    snprintf(err, len, "cannot read options file %s: %s", file, strerror(errno));
    return 1;
  }
  while (!rc && getline(&line, &cap, fp) >= 0) rc = ExpandLine(out, line, file, ++lineno, depth, err, len);
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
static int ExpandArgs(StrList *out, int argc, char **argv, char err[], size_t len)
{
  if (ListPush(out, argv[0], strlen(argv[0]))) return 1;
  for (int i = 1; i < argc; ++i) {
    const int file = ValidKey(argv[i]) && !strcasecmp(argv[i], "-options_file");
    const int yaml = ValidKey(argv[i]) && !strcasecmp(argv[i], "-options_file_yaml");

    if (file || yaml) {
      if (i + 1 >= argc || argv[i + 1][0] == '-') {
        snprintf(err, len, "option %s needs a file name", argv[i]);
        return 1;
      }
      if (yaml || IsYAMLName(argv[i + 1])) {
        if (PassYAML(out, argv[i], argv[i + 1], err, len)) return 1;
      } else if (ExpandFile(out, argv[i + 1], 1, err, len)) return 1;
      ++i;
    } else if (ListPush(out, argv[i], strlen(argv[i]))) {
      snprintf(err, len, "out of memory reading options");
      return 1;
    }
  }
  return 0;
}

int ContactOptionsExpandFiles(MPI_Comm comm, int *argc, char ***argv, char err[], size_t len)
{
  int   rank, info[2] = {0, 0}; /* error, bytes of the packed arguments */
  char *packed = NULL;

  err[0] = 0;
  (void)MPI_Comm_rank(comm, &rank);
  if (!rank) {
    StrList l = {0, 0, NULL};

    if (ExpandArgs(&l, *argc, *argv, err, len)) info[0] = 1;
    else {
      size_t bytes = 0, off = 0;
      for (int i = 0; i < l.n; ++i) bytes += strlen(l.s[i]) + 1;
      if (!(packed = (char *)malloc(bytes))) info[0] = 1;
      else {
        for (int i = 0; i < l.n; ++i) {
          size_t n = strlen(l.s[i]) + 1;
          memcpy(packed + off, l.s[i], n);
          off += n;
        }
        info[1] = (int)bytes;
      }
    }
    ListFree(&l);
  }
  (void)MPI_Bcast(info, 2, MPI_INT, 0, comm);
  if (info[0]) {
    (void)MPI_Bcast(err, (int)len, MPI_CHAR, 0, comm);
    free(packed);
    return 1;
  }
  if (rank && !(packed = (char *)malloc((size_t)info[1]))) {
    snprintf(err, len, "out of memory reading options");
    return 1;
  }
  (void)MPI_Bcast(packed, info[1], MPI_CHAR, 0, comm);
  for (int off = 0; off < info[1];) {
    size_t n = strlen(packed + off);
    if (ListPush(&expanded, packed + off, n)) {
      free(packed);
      snprintf(err, len, "out of memory reading options");
      return 1;
    }
    off += (int)n + 1;
  }
  free(packed);
  *argc = expanded.n;
  *argv = expanded.s;
  return 0;
}

void ContactOptionsFinalize(void)
{
  ListFree(&expanded);
}

/* The value quoted by PETSc's message, and what it should have been. */
static PetscBool ParseValueError(const char fun[], const char mess[], char value[], size_t len, const char **expected)
{
  const char *v = NULL, *end = NULL;

  if (!fun || !mess) return PETSC_FALSE;
  if (!strcmp(fun, "PetscOptionsStringToReal") || !strcmp(fun, "PetscOptionsStringToScalar")) *expected = "a number";
  else if (!strcmp(fun, "PetscOptionsStringToInt")) *expected = "an integer";
  else if (!strcmp(fun, "PetscOptionsStringToBool")) *expected = "true or false";
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

PetscBool ContactOptionsDescribeValueError(const char fun[], const char mess[], char buf[], size_t len)
{
  char        value[256], names[512] = "", *all = NULL, *tok, *save = NULL;
  const char *expected, *name = NULL, *val = NULL;
  int         found = 0;

  if (!ParseValueError(fun, mess, value, sizeof(value), &expected)) return PETSC_FALSE;
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
