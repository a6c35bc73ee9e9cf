/* Validation of a Gmsh mesh file before PETSc reads it.

   PETSc's Gmsh reader (DMPlexCreateGmsh, 3.18) trusts its input: a wrong count,
   a node reference outside $Nodes, a word longer than its 4096-byte buffer, a
   physical name not right after its tag or an element type it does not know
   makes it allocate absurd sizes, write past its buffers or stop with a
   traceback. MeshCheckFile reads the file once, line by line, with plain stdio
   on rank 0, and checks everything that reader relies on:

   - the sections in the reader's order: $MeshFormat, [$PhysicalNames],
     $Entities (4.1 only), $Nodes, $Elements, then any sections but $Periodic;
     $Comments blocks between sections; every section closed by its $End
     marker; blank lines are ignored;
   - ASCII format 2.2 (data size 8) or 4.1 (data size 4 or 8); binary files and
     other versions are refused with a hint;
   - every count an integer in [0, 1e8] that matches the lines that follow;
     every field a well-formed integer or finite real, nothing after the last;
   - node tags in [1, 1e8] and unique; element types the reader supports (of
     3D types, the second-order Tet10 and Hex27 alone; another 3D type is
     refused by name), with the number of tags and nodes their type implies, nodes that
     exist and are not repeated; physical tags nonnegative; $PhysicalNames
     entries `dim tag "name"` (dim 0-3, tag > 0, 1-127 printable characters);
   - and what the reader and the solver need of the topology. A mesh with 3D
     elements is a 3D body's: a single 3D element type (its cells; the 2D
     elements are faces of its physical surfaces). Otherwise: at least one
     2D element and a single 2D element type, no edge shared by more than two 2D
     elements (duplicated or overlapping cells), every line element an edge of
     a 2D element and every point element a corner of one, and every node in
     the plane z = 0.

   Nothing is allocated from a count: arrays grow with the lines actually read
   and a line holds at most MSH_LINE_MAX characters, so memory is bounded by the
   file's size. The scan is plain C that writes a verdict (a code and "mesh FILE,
   line N: what is wrong") instead of raising PETSc errors, because an error
   raised on rank 0 alone would leave the other ranks waiting; the verdict is
   broadcast and every rank raises the same error. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mshcheck.h"

#define MSH_MAX_COUNT 100000000L /* counts and node tags; larger is taken as corrupt */
#define MSH_LINE_MAX  4095       /* PETSc reads words into 4096-byte buffers */
#define MSH_BUF_LEN   (1 << 20)
#define MSH_NAME_MAX  127 /* PETSc copies a physical name into 130 bytes */
#define MSH_MAX_TAGS  64  /* tags of a 2.2 element (PETSc's buffer holds tags + nodes <= 1004) */
#define MSH_MAX_PHYS  16  /* physical tags of a 4.1 entity (PETSc's GMSH_MAX_TAGS) */
#define MSH_MAX_NODES 121 /* nodes of the largest 2D element PETSc reads */
#define MSH_MSG_LEN   (PETSC_MAX_PATH_LEN + 512)

typedef enum {
  MSH_OK,
  MSH_OPEN,
  MSH_READ,
  MSH_BAD,
  MSH_3D /* a 2D mesh off the plane z = 0 (a 3D body's surfaces without its volume), or a rigid body's 3D mesh */
} MshVerdict;

/* An element type that PETSc's reader supports (its GmshCellTable) and the solver takes. */
typedef struct {
  int         type, dim, nverts, nnodes;
  const char *shape;
} MshType;

static const MshType mshTypes[] = {
  {15, 0, 1, 1, "point"},
  {1, 1, 2, 2, "line"},
  {8, 1, 2, 3, "line"},
  {26, 1, 2, 4, "line"},
  {27, 1, 2, 5, "line"},
  {28, 1, 2, 6, "line"},
  {62, 1, 2, 7, "line"},
  {63, 1, 2, 8, "line"},
  {64, 1, 2, 9, "line"},
  {65, 1, 2, 10, "line"},
  {66, 1, 2, 11, "line"},
  {2, 2, 3, 3, "triangle"},
  {9, 2, 3, 6, "triangle"},
  {21, 2, 3, 10, "triangle"},
  {23, 2, 3, 15, "triangle"},
  {25, 2, 3, 21, "triangle"},
  {42, 2, 3, 28, "triangle"},
  {43, 2, 3, 36, "triangle"},
  {44, 2, 3, 45, "triangle"},
  {45, 2, 3, 55, "triangle"},
  {46, 2, 3, 66, "triangle"},
  {3, 2, 4, 4, "quadrilateral"},
  {10, 2, 4, 9, "quadrilateral"},
  {16, 2, 4, 8, "quadrilateral"},
  {36, 2, 4, 16, "quadrilateral"},
  {37, 2, 4, 25, "quadrilateral"},
  {38, 2, 4, 36, "quadrilateral"},
  {47, 2, 4, 49, "quadrilateral"},
  {48, 2, 4, 64, "quadrilateral"},
  {49, 2, 4, 81, "quadrilateral"},
  {50, 2, 4, 100, "quadrilateral"},
  {51, 2, 4, 121, "quadrilateral"},
  {11, 3, 4, 10, "tetrahedron"},
  {12, 3, 8, 27, "hexahedron"},
};

/* The other 3D types of PETSc's table: known to the reader, not to the solver
   (a 3D body is of second-order Tet10 or Hex27 cells), by shape. */
static const int msh3DTypes[] = {4, 29, 30, 31, 71, 72, 73, 74, 75, 5, 17, 92, 93, 94, 95, 96, 97, 98, 6, 13, 90, 91, 106, 107, 108, 109, 110, 7, 14, 118, 119, 120, 121, 122, 123, 124};

static const char *Msh3DShape(long type)
{
  switch (type) {
  case 4: return "4-node (first-order) tetrahedron";
  case 5: return "8-node (first-order) hexahedron";
  case 17: return "20-node (serendipity) hexahedron";
  case 6: case 13: case 90: case 91: case 106: case 107: case 108: case 109: case 110: return "prism";
  case 7: case 14: case 118: case 119: case 120: case 121: case 122: case 123: case 124: return "pyramid";
  case 29: case 30: case 31: case 71: case 72: case 73: case 74: case 75: return "tetrahedron of order above 2";
  default: return "hexahedron of order above 2";
  }
}

/* Open-addressing hash table from nonzero 64-bit keys to int values. */
typedef struct {
  uint64_t *key;
  int      *val;
  size_t    cap, n; /* cap is 0 or a power of 2 at least 2 n */
  int       bits;   /* cap = 2^bits */
} MshHash;

typedef struct {
  const char    *path;
  FILE          *fp;
  char          *buf; /* MSH_BUF_LEN + 1 bytes; the unread bytes are buf[pos, end) */
  size_t         pos, end;
  int            eof;
  long           lineno; /* number of the current line */
  char          *line;   /* the current line, NUL-terminated, without its newline */
  MshVerdict     verdict;
  char          *msg;
  size_t         msglen;
  const char    *ctxName; /* "element", "node", ...: prefixes field errors with "<ctxName> <ctxId>: " */
  long           ctxId;
  int            format; /* 22 or 41 */
  long           nnodes, capnodes;
  int           *node;             /* per node: tag, line */
  long           maxTag;            /* largest node tag */
  int           *nodeMap;          /* tag -> node index if the tags are dense (up to 4 nnodes + 1024) */
  MshHash        nodes;             /* tag -> node index otherwise */
  int           *stamp;             /* per node: the last element (1, 2, ...) that listed it */
  MshHash        entities;          /* (dim, tag) of the 4.1 entities */
  long           nelems, ncells, capcells, nsegs, capsegs, npoints, cappoints;
  int           *cell;  /* per 2D element: 4 corners (the 4th -1 on a triangle), element number, line */
  int           *seg;   /* per line element: 2 corners, element number, line */
  int           *point; /* per point element: node, element number, line */
  const MshType *cellType; /* type of the first 2D element */
  const MshType *solidType; /* type of the first 3D element */
  long           nsolids, solidTypeLine, capsolids;
  int           *solid; /* per 3D element: 8 corners (the last 4 -1 on a tetrahedron), element number, line */
  long           offPlaneLine; /* the first node off the plane z = 0 (0: none), at z */
  double         offPlaneZ;
  long           cellTypeLine, endElementsLine;
  int            curves; /* a rigid body's mesh: its lines are what it needs, cells are ignored */
} MshCheck;

/* Writes the message "mesh FILE, line N: [ctx ctxId: ]..." unless a verdict is already set. */
static void MshFailV(MshCheck *c, MshVerdict v, long line, const char *ctx, long ctxId, const char *fmt, va_list ap)
{
  int k;

  if (c->verdict != MSH_OK) return;
  c->verdict = v;
  if (ctx) k = snprintf(c->msg, c->msglen, "mesh %s, line %ld: %s %ld: ", c->path, line, ctx, ctxId);
  else k = snprintf(c->msg, c->msglen, "mesh %s, line %ld: ", c->path, line);
  if (k >= 0 && (size_t)k < c->msglen) vsnprintf(c->msg + k, c->msglen - (size_t)k, fmt, ap);
}

/* Records a content error at the current line (prefixed by the current element
   or node, if any); returns 1 so that callers can write return MshFail(...). */
static PETSC_ATTRIBUTE_FORMAT(2, 3) int MshFail(MshCheck *c, const char *fmt, ...)
{
  va_list ap;

  va_start(ap, fmt);
  MshFailV(c, MSH_BAD, c->lineno, c->ctxName, c->ctxId, fmt, ap);
  va_end(ap);
  return 1;
}

/* Records a content error at a given line, without a prefix; returns 1. */
static PETSC_ATTRIBUTE_FORMAT(3, 4) int MshFailAt(MshCheck *c, long line, const char *fmt, ...)
{
  va_list ap;

  va_start(ap, fmt);
  MshFailV(c, MSH_BAD, line, NULL, 0, fmt, ap);
  va_end(ap);
  return 1;
}

/* Records that the mesh is 3D, with what shows it; returns 1. */
static PETSC_ATTRIBUTE_FORMAT(2, 3) int MshFail3D(MshCheck *c, const char *fmt, ...)
{
  va_list ap;

  va_start(ap, fmt);
  MshFailV(c, MSH_3D, c->lineno, c->ctxName, c->ctxId, fmt, ap);
  va_end(ap);
  return 1;
}

/* A printable excerpt of s for messages: at most 32 characters (up to the first
   white space if word), other than printable ASCII shown as '?'. */
static const char *MshShow(const char *s, int word, char out[40])
{
  size_t i = 0, j;

  while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
  for (; s[i] && i < 32; ++i) {
    const unsigned char ch = (unsigned char)s[i];
    if (word && (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f')) break;
    out[i] = (ch >= 0x20 && ch < 0x7f) ? (char)ch : '?';
  }
  j = i;
  while (j > 0 && out[j - 1] == ' ') --j;
  if (s[i] && i == 32) {
    memcpy(out + j, "...", 3);
    j += 3;
  }
  out[j] = 0;
  return out;
}

/* White space inside a line, as PETSc's reader skips it. */
static int MshSpace(char ch)
{
  return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f';
}

/* s past its white space. */
static const char *MshSkip(const char *s)
{
  while (MshSpace(*s)) ++s;
  return s;
}

/* Whether the line is the word w, up to white space around it. */
static int MshIs(const char *line, const char *w)
{
  const size_t n = strlen(w);

  line = MshSkip(line);
  return !strncmp(line, w, n) && !*MshSkip(line + n);
}

/* Reads the next line into c->line: 1 if there is one, 0 at the end of the file,
   -1 after a line too long, a NUL byte or a read error (verdict set). */
static int MshReadLine(MshCheck *c)
{
  for (;;) {
    char  *start = c->buf + c->pos, *nl;
    size_t avail = c->end - c->pos, got;

    nl = avail ? (char *)memchr(start, '\n', avail) : NULL;
    if (nl || (c->eof && avail)) {
      const size_t n = nl ? (size_t)(nl - start) : avail;

      c->pos += nl ? n + 1 : n;
      c->lineno++;
      if (n > MSH_LINE_MAX) return -MshFail(c, "line longer than %d characters (not a Gmsh ASCII file?)", MSH_LINE_MAX);
      if (memchr(start, 0, n)) return -MshFail(c, "NUL byte (binary data in an ASCII Gmsh file)");
      start[n] = 0;
      c->line  = start;
      return 1;
    }
    if (c->eof) return 0;
    if (avail > MSH_LINE_MAX) {
      c->lineno++;
      return -MshFail(c, "line longer than %d characters (not a Gmsh ASCII file?)", MSH_LINE_MAX);
    }
    memmove(c->buf, start, avail);
    c->pos = 0;
    c->end = avail;
    got    = fread(c->buf + c->end, 1, MSH_BUF_LEN - c->end, c->fp);
    if (!got) {
      if (ferror(c->fp)) {
        if (c->verdict == MSH_OK) {
          snprintf(c->msg, c->msglen, "cannot read mesh file %s: %s", c->path, strerror(errno));
          c->verdict = MSH_READ;
        }
        return -1;
      }
      c->eof = 1;
    }
    c->end += got;
  }
}

/* The next non-blank line: 1, 0 at the end of the file, -1 on error. */
static int MshNext(MshCheck *c)
{
  int r;

  while ((r = MshReadLine(c)) == 1 && !*MshSkip(c->line)) { }
  return r;
}

/* The next section marker, past any $Comments blocks (which PETSc's reader
   skips wherever it looks for a section): 1, 0 at the end of the file, -1 on error. */
static int MshNextSection(MshCheck *c)
{
  for (;;) {
    long start;
    int  r = MshNext(c);

    if (r <= 0 || !MshIs(c->line, "$Comments")) return r;
    start = c->lineno;
    for (;;) {
      if ((r = MshReadLine(c)) < 0) return -1;
      if (!r) return -MshFailAt(c, start, "$Comments has no $EndComments before the end of the file");
      if (MshIs(c->line, "$EndComments")) break;
      /* PETSc ends the comment at the first word $EndComments; MeshReadPhysicalNames
         looks for a line that starts with $PhysicalNames */
      if (strstr(c->line, "$EndComments")) return -MshFail(c, "$EndComments must stand on a line of its own");
      if (*MshSkip(c->line) == '$') return -MshFail(c, "a line in $Comments starts with '$' (unclosed $Comments?)");
    }
  }
}

/* Reads the next section marker and checks that it is want; after names the
   section before it for the message. */
static int MshExpectSection(MshCheck *c, const char *want, const char *after)
{
  char show[40];
  int  r = MshNextSection(c);

  if (r < 0) return 1;
  if (!r) return MshFailAt(c, c->lineno + 1, "end of file where %s was expected (after %s)", want, after);
  if (!MshIs(c->line, want)) return MshFail(c, "expected %s after %s, found '%s'", want, after, MshShow(c->line, 0, show));
  return 0;
}

/* The next data line of section sec, the k-th (from 0) of n items: a marker or
   the end of the file there means the section holds fewer lines than declared. */
static int MshData(MshCheck *c, const char *sec, const char *items, long k, long n)
{
  char show[40];
  int  r = MshNext(c);

  if (r < 0) return 1;
  if (!r) return MshFailAt(c, c->lineno + 1, "end of file in %s after %ld of the %ld %s it declares", sec, k, n, items);
  if (*MshSkip(c->line) == '$') return MshFail(c, "%s declares %ld %s, but '%s' comes after %ld of them", sec, n, items, MshShow(c->line, 0, show), k);
  return 0;
}

/* Reads the end marker of section sec, which declared n items. */
static int MshExpectEnd(MshCheck *c, const char *sec, const char *end, long n, const char *items)
{
  char show[40];
  int  r = MshNext(c);

  if (r < 0) return 1;
  if (!r) return MshFailAt(c, c->lineno + 1, "end of file where %s was expected", end);
  if (MshIs(c->line, end)) return 0;
  if (*MshSkip(c->line) == '$') return MshFail(c, "expected %s, found '%s'", end, MshShow(c->line, 0, show));
  return MshFail(c, "%s declares %ld %s, but more lines follow ('%s' where %s was expected)", sec, n, items, MshShow(c->line, 0, show), end);
}

/* Parses the integer at *s, in [lo, hi], and moves *s past it: optional sign
   and decimal digits, as PETSc's fscanf("%d") reads them. */
static int MshInt(MshCheck *c, const char **s, long lo, long hi, const char *what, long *v)
{
  const char *p = MshSkip(*s), *q = p;
  char        show[40];
  int         neg = 0, big = 0;
  long        x   = 0;

  if (!*p) return MshFail(c, "%s missing", what);
  if (*q == '+' || *q == '-') neg = *q++ == '-';
  if (*q < '0' || *q > '9') return MshFail(c, "%s '%s' is not an integer", what, MshShow(p, 1, show));
  for (; *q >= '0' && *q <= '9'; ++q) {
    if (x > (LONG_MAX - 9) / 10) big = 1;
    else x = 10 * x + (*q - '0');
  }
  if (*q && !MshSpace(*q)) return MshFail(c, "%s '%s' is not an integer", what, MshShow(p, 1, show));
  x = neg ? -x : x;
  if (big || x < lo || x > hi) return MshFail(c, "%s %s is out of range [%ld, %ld]", what, MshShow(p, 1, show), lo, hi);
  *v = x;
  *s = q;
  return 0;
}

/* The end of the decimal real at p if it is certainly finite (at most 20
   digits before the point, exponent at most 280), else NULL. */
static const char *MshDecimal(const char *p)
{
  int  idig = 0, fdig = 0, edig = 0, eneg = 0;
  long e    = 0;

  if (*p == '+' || *p == '-') ++p;
  for (; *p >= '0' && *p <= '9'; ++p) ++idig;
  if (*p == '.')
    for (++p; *p >= '0' && *p <= '9'; ++p) ++fdig;
  if (!idig && !fdig) return NULL;
  if (*p == 'e' || *p == 'E') {
    ++p;
    if (*p == '+' || *p == '-') eneg = *p++ == '-';
    for (; *p >= '0' && *p <= '9' && edig < 5; ++p, ++edig) e = 10 * e + (*p - '0');
    if (!edig || edig == 5) return NULL;
  }
  if (*p && !MshSpace(*p)) return NULL;
  if (idig > 20 || (!eneg && e > 280)) return NULL;
  return p;
}

/* Checks that *s starts with a finite real, as PETSc's fscanf("%lg") reads
   it, and moves *s past it. Plain decimals are checked by MshDecimal, the rest
   (long, huge, hexadecimal, nan, inf) by strtod. */
static int MshReal(MshCheck *c, const char **s, const char *what)
{
  const char *p = MshSkip(*s), *q;
  char       *end;
  char        show[40];
  double      v;

  if (!*p) return MshFail(c, "%s missing", what);
  if ((q = MshDecimal(p))) {
    *s = q;
    return 0;
  }
  v = strtod(p, &end);
  if (end == p || (*end && !MshSpace(*end))) return MshFail(c, "%s '%s' is not a number", what, MshShow(p, 1, show));
  if (!isfinite(v)) return MshFail(c, "%s '%s' is not a finite number", what, MshShow(p, 1, show));
  *s = end;
  return 0;
}

/* Checks that nothing but white space follows the last field. */
static int MshEnd(MshCheck *c, const char *s, const char *last)
{
  char show[40];

  s = MshSkip(s);
  if (*s) return MshFail(c, "unexpected '%s' after the %s", MshShow(s, 0, show), last);
  return 0;
}

/* The next data line of section sec, which should hold its what. */
static int MshLine(MshCheck *c, const char *sec, const char *what)
{
  char show[40];
  int  r = MshNext(c);

  if (r < 0) return 1;
  if (!r) return MshFailAt(c, c->lineno + 1, "end of file where the %s of %s was expected", what, sec);
  if (*MshSkip(c->line) == '$') return MshFail(c, "the %s of %s is missing (found '%s')", what, sec, MshShow(c->line, 0, show));
  return 0;
}

/* A line with a single count in [0, MSH_MAX_COUNT]. */
static int MshCount(MshCheck *c, const char *sec, long *n)
{
  const char *s;

  if (MshLine(c, sec, "count")) return 1;
  s = c->line;
  if (MshInt(c, &s, 0, MSH_MAX_COUNT, "count", n)) return 1;
  return MshEnd(c, s, "count");
}

/* The nonzero key of the pair (a, b) of nonnegative ints. */
static uint64_t MshHashKey(long a, long b)
{
  return ((uint64_t)(uint32_t)a << 32 | (uint32_t)b) + 1;
}

/* The home slot of key (Fibonacci hashing). */
static size_t MshHashSlot(const MshHash *h, uint64_t key)
{
  return (size_t)((key * 0x9E3779B97F4A7C15ULL) >> (64 - h->bits));
}

/* Frees the table and leaves it empty. */
static void MshHashFree(MshHash *h)
{
  free(h->key);
  free(h->val);
  memset(h, 0, sizeof(*h));
}

/* Makes the table hold at least n keys at load 1/2; nonzero when out of memory. */
static int MshHashReserve(MshHash *h, size_t n)
{
  MshHash g = {NULL, NULL, 64, 0, 6};

  if (2 * n <= h->cap) return 0;
  while (g.cap < 2 * n) {
    g.cap *= 2;
    g.bits++;
  }
  g.key = (uint64_t *)calloc(g.cap, sizeof(uint64_t));
  g.val = (int *)malloc(g.cap * sizeof(int));
  if (!g.key || !g.val) {
    free(g.key);
    free(g.val);
    return 1;
  }
  for (size_t i = 0; i < h->cap; ++i) {
    size_t j;
    if (!h->key[i]) continue;
    for (j = MshHashSlot(&g, h->key[i]); g.key[j]; j = (j + 1) & (g.cap - 1)) { }
    g.key[j] = h->key[i];
    g.val[j] = h->val[i];
  }
  g.n = h->n;
  MshHashFree(h);
  *h = g;
  return 0;
}

/* The value of key, or NULL if absent. */
static int *MshHashGet(const MshHash *h, uint64_t key)
{
  if (!h->cap) return NULL;
  for (size_t i = MshHashSlot(h, key);; i = (i + 1) & (h->cap - 1)) {
    if (h->key[i] == key) return &h->val[i];
    if (!h->key[i]) return NULL;
  }
}

/* The value of key, inserted with value -1 if absent; NULL when out of memory. */
static int *MshHashPut(MshHash *h, uint64_t key)
{
  size_t i;

  if (2 * (h->n + 1) > h->cap && MshHashReserve(h, h->cap ? h->cap : 32)) return NULL;
  for (i = MshHashSlot(h, key); h->key[i]; i = (i + 1) & (h->cap - 1))
    if (h->key[i] == key) return &h->val[i];
  h->key[i] = key;
  h->val[i] = -1;
  h->n++;
  return &h->val[i];
}

/* Makes room for one more item of per ints in *a, which holds cnt of *cap items. */
static int MshGrow(MshCheck *c, int **a, long *cap, long cnt, size_t per)
{
  int *q;
  long ncap;

  if (cnt < *cap) return 0;
  ncap = *cap ? 2 * *cap : 1024;
  q    = (int *)realloc(*a, (size_t)ncap * per * sizeof(int));
  if (!q) return MshFail(c, "out of memory");
  *a   = q;
  *cap = ncap;
  return 0;
}

/* The tag of the node of index i. */
static int MshNodeTag(const MshCheck *c, int i)
{
  return c->node[2 * i];
}

/* Adds the node of tag id, read at the current line. */
static int MshAddNode(MshCheck *c, long id)
{
  if (MshGrow(c, &c->node, &c->capnodes, c->nnodes, 2)) return 1;
  c->node[2 * c->nnodes]     = (int)id;
  c->node[2 * c->nnodes + 1] = (int)c->lineno;
  c->nnodes++;
  if (id > c->maxTag) c->maxTag = id;
  return 0;
}

/* Maps the node tags to node indices once $Nodes is read (an array if the
   tags are dense, a hash table otherwise); tags must be unique. */
static int MshIndexNodes(MshCheck *c)
{
  const int dense = c->maxTag <= 4 * c->nnodes + 1024;

  if (!(c->stamp = (int *)calloc((size_t)c->nnodes + 1, sizeof(int)))) return MshFail(c, "out of memory");

  if (dense) {
    if (!(c->nodeMap = (int *)malloc((size_t)(c->maxTag + 1) * sizeof(int)))) return MshFail(c, "out of memory");
    for (long i = 0; i <= c->maxTag; ++i) c->nodeMap[i] = -1;
  } else if (MshHashReserve(&c->nodes, (size_t)c->nnodes)) return MshFail(c, "out of memory");
  for (long i = 0; i < c->nnodes; ++i) {
    const int id = c->node[2 * i];
    int      *slot;

    if (dense) slot = &c->nodeMap[id];
    else if (!(slot = MshHashPut(&c->nodes, (uint64_t)id))) return MshFail(c, "out of memory");
    if (*slot >= 0) return MshFailAt(c, c->node[2 * i + 1], "node %d is defined a second time (first at line %d)", id, c->node[2 * *slot + 1]);
    *slot = (int)i;
  }
  return 0;
}

/* The index of the node of tag id, or -1. */
static int MshNodeIndex(const MshCheck *c, long id)
{
  const int *slot;

  if (id < 1 || id > c->maxTag) return -1;
  if (c->nodeMap) return c->nodeMap[id];
  slot = MshHashGet(&c->nodes, (uint64_t)id);
  return slot ? *slot : -1;
}

/* The supported type of Gmsh number type, or NULL after setting the verdict. */
static const MshType *MshTypeOf(MshCheck *c, long type)
{
  for (size_t i = 0; i < sizeof(mshTypes) / sizeof(mshTypes[0]); ++i)
    if (mshTypes[i].type == type) return &mshTypes[i];
  for (size_t i = 0; i < sizeof(msh3DTypes) / sizeof(msh3DTypes[0]); ++i)
    if (msh3DTypes[i] == type) {
      MshFail(c, "Gmsh element type %ld, a %s: a 3D body takes second-order Tet10 (type 11) or Hex27 (type 12) cells (Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 0)", type, Msh3DShape(type));
      return NULL;
    }
  MshFail(c, "unknown or unsupported Gmsh element type %ld", type);
  return NULL;
}

/* Parses the k-th node of an element of type t, after ntags tags (-1 in MSH
   4.1, which has none), into the node's index. */
static int MshNodeRef(MshCheck *c, const char **s, const MshType *t, long ntags, int k, int *idx)
{
  long        v;
  const char *p = MshSkip(*s);

  if (!*p && ntags >= 0) return MshFail(c, "lists %d nodes after its %ld tags, but a %d-node %s has %d", k, ntags, t->nnodes, t->shape, t->nnodes);
  if (!*p) return MshFail(c, "lists %d nodes, but a %d-node %s has %d", k, t->nnodes, t->shape, t->nnodes);
  if (MshInt(c, s, LONG_MIN, LONG_MAX, "node", &v)) return 1;
  if ((*idx = MshNodeIndex(c, v)) < 0) {
    c->ctxName = NULL;
    return MshFail(c, "element %ld refers to node %ld which is not in $Nodes", c->ctxId, v);
  }
  return 0;
}

/* Records an element of type t, number id, whose nodes have indices idx[]. */
static int MshAddElement(MshCheck *c, const MshType *t, long id, const int idx[])
{
  c->nelems++;
  for (int i = 0; i < t->nnodes; ++i) {
    if (c->stamp[idx[i]] == (int)c->nelems) return MshFail(c, "element %ld lists node %d twice", id, MshNodeTag(c, idx[i]));
    c->stamp[idx[i]] = (int)c->nelems;
  }
  if (t->dim == 3) {
    if (!c->solidType) {
      c->solidType     = t;
      c->solidTypeLine = c->lineno;
    } else if (t != c->solidType)
      return MshFail(c, "element %ld is a %d-node %s, but the 3D element at line %ld is a %d-node %s; a body has one cell type", id, t->nnodes, t->shape, c->solidTypeLine, c->solidType->nnodes, c->solidType->shape);
    {
      int *e;
      if (MshGrow(c, &c->solid, &c->capsolids, c->nsolids, 10)) return 1;
      e = c->solid + 10 * c->nsolids++;
      for (int i = 0; i < 8; ++i) e[i] = i < t->nverts ? idx[i] : -1;
      e[8] = (int)id;
      e[9] = (int)c->lineno;
    }
  } else if (t->dim == 2) {
    int *e;
    if (!c->cellType) {
      c->cellType     = t;
      c->cellTypeLine = c->lineno;
    } else if (t != c->cellType)
      return MshFail(c, "element %ld is a %d-node %s, but the 2D element at line %ld is a %d-node %s; PETSc's reader takes one 2D element type", id, t->nnodes, t->shape, c->cellTypeLine, c->cellType->nnodes, c->cellType->shape);
    if (MshGrow(c, &c->cell, &c->capcells, c->ncells, 6)) return 1;
    e = c->cell + 6 * c->ncells++;
    for (int i = 0; i < 4; ++i) e[i] = i < t->nverts ? idx[i] : -1;
    e[4] = (int)id;
    e[5] = (int)c->lineno;
  } else if (t->dim == 1) {
    int *e;
    if (MshGrow(c, &c->seg, &c->capsegs, c->nsegs, 4)) return 1;
    e    = c->seg + 4 * c->nsegs++;
    e[0] = idx[0];
    e[1] = idx[1];
    e[2] = (int)id;
    e[3] = (int)c->lineno;
  } else {
    int *e;
    if (MshGrow(c, &c->point, &c->cappoints, c->npoints, 3)) return 1;
    e    = c->point + 3 * c->npoints++;
    e[0] = idx[0];
    e[1] = (int)id;
    e[2] = (int)c->lineno;
  }
  return 0;
}

/* $MeshFormat: "version file-type data-size"; sets c->format. */
static int MshReadFormat(MshCheck *c)
{
  const char *s, *p;
  char       *end;
  char        show[40];
  double      version;
  long        type, size;
  int         r = MshNextSection(c);

  if (r < 0) return 1;
  if (!r) return MshFailAt(c, c->lineno + 1, c->lineno ? "no $MeshFormat before the end of the file" : "empty file, expected $MeshFormat");
  if (!MshIs(c->line, "$MeshFormat")) return MshFail(c, "expected $MeshFormat (a Gmsh ASCII file), found '%s'", MshShow(c->line, 0, show));
  if (MshLine(c, "$MeshFormat", "version line")) return 1;
  s       = c->line;
  p       = MshSkip(s);
  version = strtod(p, &end);
  if (end == p || (*end && !MshSpace(*end)) || !isfinite(version)) return MshFail(c, "Gmsh format version '%s' is not a number", MshShow(p, 1, show));
  s = end;
  if (fabs(version - 2.2) < 1e-9) c->format = 22;
  else if (fabs(version - 4.1) < 1e-9) c->format = 41;
  else return MshFail(c, "Gmsh format version %s is not supported: write ASCII 2.2 (gmsh -format msh22) or 4.1", MshShow(p, 1, show));
  if (MshInt(c, &s, LONG_MIN, LONG_MAX, "file type", &type)) return 1;
  if (type == 1) return MshFail(c, "binary Gmsh file; write an ASCII file (gmsh -format msh22, without -bin)");
  if (type != 0) return MshFail(c, "file type %ld is neither 0 (ASCII) nor 1 (binary)", type);
  if (MshInt(c, &s, LONG_MIN, LONG_MAX, "data size", &size)) return 1;
  if (c->format == 22 && size != 8) return MshFail(c, "data size %ld is not 8 (sizeof(double)) as MSH 2.2 requires", size);
  if (c->format == 41 && size != 4 && size != 8) return MshFail(c, "data size %ld is neither 4 nor 8", size);
  if (MshEnd(c, s, "data size")) return 1;
  return MshExpectEnd(c, "$MeshFormat", "$EndMeshFormat", 1, "line");
}

/* $PhysicalNames: a count, then `dim tag "name"` per line. PETSc reads the name
   from the character after the one that ends the tag, so exactly one white
   space character must separate them. */
static int MshReadPhysicalNames(MshCheck *c)
{
  long n;

  if (MshCount(c, "$PhysicalNames", &n)) return 1;
  for (long k = 0; k < n; ++k) {
    const char *s, *q;
    long        dim, tag;

    if (MshData(c, "$PhysicalNames", "names", k, n)) return 1;
    s = c->line;
    if (MshInt(c, &s, 0, 3, "physical dimension", &dim) || MshInt(c, &s, 1, INT_MAX, "physical tag", &tag)) return 1;
    if (!*s) return MshFail(c, "physical name missing after tag %ld", tag);
    if (s[1] != '"') return MshFail(c, "physical name of tag %ld must follow it after one space, in double quotes", tag);
    for (q = s + 2; *q && *q != '"'; ++q)
      if ((unsigned char)*q < 0x20 || *q == 0x7f) return MshFail(c, "physical name of tag %ld contains a control character", tag);
    if (!*q) return MshFail(c, "physical name of tag %ld has no closing quote", tag);
    if (q == s + 2) return MshFail(c, "physical name of tag %ld is empty", tag);
    if (q - (s + 2) > MSH_NAME_MAX) return MshFail(c, "physical name of tag %ld is longer than %d characters", tag, MSH_NAME_MAX);
    if (MshEnd(c, q + 1, "physical name")) return 1;
  }
  return MshExpectEnd(c, "$PhysicalNames", "$EndPhysicalNames", n, "names");
}

/* $Entities (4.1): counts of points, curves, surfaces, volumes, then per entity
   "tag bounding-box nphys phys... [nbound bound...]" (a point has x y z). */
static int MshReadEntities(MshCheck *c)
{
  static const char *kind[4] = {"point", "curve", "surface", "volume"};
  const char        *s;
  long               count[4], total = 0;

  if (MshLine(c, "$Entities", "counts line")) return 1;
  s = c->line;
  for (int d = 0; d < 4; ++d) {
    if (MshInt(c, &s, 0, MSH_MAX_COUNT, "number of entities", &count[d])) return 1;
    total += count[d];
  }
  if (MshEnd(c, s, "number of volumes")) return 1;
  for (int d = 0; d < 4; ++d) {
    for (long k = 0; k < count[d]; ++k) {
      long   tag, nphys, nbound, v;
      int   *slot;

      if (MshData(c, "$Entities", "entities", k, count[d])) return 1;
      s = c->line;
      if (MshInt(c, &s, 1, INT_MAX, "entity tag", &tag)) return 1;
      c->ctxName = kind[d];
      c->ctxId   = tag;
      for (int i = 0; i < (d ? 6 : 3); ++i)
        if (MshReal(c, &s, d ? "bounding box coordinate" : "coordinate")) return 1;
      if (MshInt(c, &s, 0, MSH_MAX_PHYS, "number of physical tags", &nphys)) return 1;
      for (long i = 0; i < nphys; ++i)
        if (MshInt(c, &s, 0, INT_MAX, "physical tag", &v)) return 1;
      if (d) {
        if (MshInt(c, &s, 0, MSH_MAX_COUNT, "number of bounding entities", &nbound)) return 1;
        for (long i = 0; i < nbound; ++i)
          if (MshInt(c, &s, INT_MIN, INT_MAX, "bounding entity", &v)) return 1;
      }
      if (MshEnd(c, s, d ? "bounding entities" : "physical tags")) return 1;
      if (!(slot = MshHashPut(&c->entities, MshHashKey(d, tag)))) return MshFail(c, "out of memory");
      if (*slot >= 0) return MshFail(c, "defined a second time");
      *slot      = (int)c->lineno;
      c->ctxName = NULL;
    }
  }
  return MshExpectEnd(c, "$Entities", "$EndEntities", total, "entities");
}

/* The coordinates "x y z" of a node; the first off the plane z = 0 is
   recorded (a 2D mesh must lie in it). */
static int MshCoordinates(MshCheck *c, const char **s)
{
  const char *z;

  if (MshReal(c, s, "x") || MshReal(c, s, "y")) return 1;
  z = MshSkip(*s);
  if (MshReal(c, s, "z") || MshEnd(c, *s, "coordinates")) return 1;
  if (strtod(z, NULL) != 0.0 && !c->offPlaneLine) {
    c->offPlaneLine = c->lineno;
    c->offPlaneZ    = strtod(z, NULL);
  }
  return 0;
}

/* A 2.2 node line: "tag x y z". */
static int MshNode22(MshCheck *c)
{
  const char *s = c->line;
  long        id;

  if (MshInt(c, &s, 1, MSH_MAX_COUNT, "node tag", &id)) return 1;
  c->ctxName = "node";
  c->ctxId   = id;
  if (MshCoordinates(c, &s)) return 1;
  c->ctxName = NULL;
  return MshAddNode(c, id);
}

/* $Nodes of MSH 2.2: a count, then a node per line. */
static int MshReadNodes22(MshCheck *c)
{
  long n;

  if (MshCount(c, "$Nodes", &n)) return 1;
  for (long k = 0; k < n; ++k)
    if (MshData(c, "$Nodes", "nodes", k, n) || MshNode22(c)) return 1;
  return MshExpectEnd(c, "$Nodes", "$EndNodes", n, "nodes") || MshIndexNodes(c);
}

/* Whether the 4.1 entity (dim, tag) is in $Entities; the reader indexes with it. */
static int MshEntity(MshCheck *c, long dim, long tag, const char *block)
{
  if (!MshHashGet(&c->entities, MshHashKey(dim, tag))) return MshFail(c, "%s block refers to entity (dimension %ld, tag %ld) which is not in $Entities", block, dim, tag);
  return 0;
}

/* $Nodes of MSH 4.1: "nblocks nnodes min max", then per block "dim tag
   parametric n", n tag lines and n coordinate lines. */
static int MshReadNodes41(MshCheck *c)
{
  const char *s;
  long        nblocks, n, tmin, tmax, total = 0, header, amin = LONG_MAX, amax = 0;

  if (MshLine(c, "$Nodes", "header line")) return 1;
  header = c->lineno;
  s      = c->line;
  if (MshInt(c, &s, 0, MSH_MAX_COUNT, "number of node blocks", &nblocks) || MshInt(c, &s, 0, MSH_MAX_COUNT, "number of nodes", &n) || MshInt(c, &s, 0, MSH_MAX_COUNT, "smallest node tag", &tmin) || MshInt(c, &s, 0, MSH_MAX_COUNT, "largest node tag", &tmax) || MshEnd(c, s, "largest node tag")) return 1;
  for (long b = 0; b < nblocks; ++b) {
    long   dim, tag, param, nb, id;
    char   sec[64];

    if (MshData(c, "$Nodes", "blocks", b, nblocks)) return 1;
    s = c->line;
    if (MshInt(c, &s, 0, 3, "entity dimension", &dim) || MshInt(c, &s, INT_MIN, INT_MAX, "entity tag", &tag) || MshInt(c, &s, 0, 1, "parametric flag", &param) || MshInt(c, &s, 0, MSH_MAX_COUNT, "number of nodes in the block", &nb) || MshEnd(c, s, "number of nodes in the block")) return 1;
    if (param) return MshFail(c, "parametric node coordinates are not supported by PETSc's reader (save without Mesh.SaveParametric)");
    if (MshEntity(c, dim, tag, "node")) return 1;
    if (nb > n - total) return MshFail(c, "node blocks hold more than the %ld nodes $Nodes declares (line %ld)", n, header);
    snprintf(sec, sizeof(sec), "the node block at line %ld", c->lineno);
    for (long k = 0; k < nb; ++k) {
      if (MshData(c, sec, "node tags", k, nb)) return 1;
      s = c->line;
      if (MshInt(c, &s, 1, MSH_MAX_COUNT, "node tag", &id) || MshEnd(c, s, "node tag") || MshAddNode(c, id)) return 1;
      amin = id < amin ? id : amin;
      amax = id > amax ? id : amax;
    }
    for (long k = 0; k < nb; ++k) {
      if (MshData(c, sec, "coordinate lines", k, nb)) return 1;
      s          = c->line;
      c->ctxName = "node";
      c->ctxId   = MshNodeTag(c, (int)(c->nnodes - nb + k));
      if (MshCoordinates(c, &s)) return 1;
      c->ctxName = NULL;
    }
    total += nb;
  }
  if (MshExpectEnd(c, "$Nodes", "$EndNodes", nblocks, "blocks")) return 1;
  if (total != n) return MshFailAt(c, header, "$Nodes declares %ld nodes, but its blocks hold %ld", n, total);
  if (n && (amin != tmin || amax != tmax)) return MshFailAt(c, header, "$Nodes declares node tags from %ld to %ld, but they run from %ld to %ld", tmin, tmax, amin, amax);
  return MshIndexNodes(c);
}

/* A 2.2 element line: "number type ntags tags... nodes...". */
static int MshElement22(MshCheck *c)
{
  const char    *s = c->line;
  long           id, type, ntags, tag;
  int            idx[MSH_MAX_NODES];
  const MshType *t;

  if (MshInt(c, &s, 1, INT_MAX, "element number", &id)) return 1;
  c->ctxName = "element";
  c->ctxId   = id;
  if (MshInt(c, &s, LONG_MIN, LONG_MAX, "type", &type) || !(t = MshTypeOf(c, type))) return 1;
  if (MshInt(c, &s, 0, MSH_MAX_TAGS, "number of tags", &ntags)) return 1;
  for (long k = 0; k < ntags; ++k)
    if (MshInt(c, &s, k < 2 ? 0 : INT_MIN, INT_MAX, k == 0 ? "physical tag" : k == 1 ? "elementary tag" : "tag", &tag)) return 1;
  for (int k = 0; k < t->nnodes; ++k)
    if (MshNodeRef(c, &s, t, ntags, k, &idx[k])) return 1;
  if (MshEnd(c, s, "last node (check the type and the number of tags)")) return 1;
  c->ctxName = NULL;
  return MshAddElement(c, t, id, idx);
}

/* $Elements of MSH 2.2: a count, then an element per line. */
static int MshReadElements22(MshCheck *c)
{
  long n;

  if (MshCount(c, "$Elements", &n)) return 1;
  for (long k = 0; k < n; ++k)
    if (MshData(c, "$Elements", "elements", k, n) || MshElement22(c)) return 1;
  return MshExpectEnd(c, "$Elements", "$EndElements", n, "elements");
}

/* $Elements of MSH 4.1: "nblocks nelements min max", then per block "dim tag
   type n" and n lines "number nodes...". */
static int MshReadElements41(MshCheck *c)
{
  const char *s;
  long        nblocks, n, tmin, tmax, total = 0, header, amin = LONG_MAX, amax = 0;

  if (MshLine(c, "$Elements", "header line")) return 1;
  header = c->lineno;
  s      = c->line;
  if (MshInt(c, &s, 0, MSH_MAX_COUNT, "number of element blocks", &nblocks) || MshInt(c, &s, 0, MSH_MAX_COUNT, "number of elements", &n) || MshInt(c, &s, 0, INT_MAX, "smallest element number", &tmin) || MshInt(c, &s, 0, INT_MAX, "largest element number", &tmax) || MshEnd(c, s, "largest element number")) return 1;
  for (long b = 0; b < nblocks; ++b) {
    long           dim, tag, type, nb, id;
    const MshType *t;
    char           sec[64];
    int            idx[MSH_MAX_NODES];

    if (MshData(c, "$Elements", "blocks", b, nblocks)) return 1;
    s = c->line;
    if (MshInt(c, &s, 0, 3, "entity dimension", &dim) || MshInt(c, &s, INT_MIN, INT_MAX, "entity tag", &tag) || MshInt(c, &s, LONG_MIN, LONG_MAX, "element type", &type) || MshInt(c, &s, 0, MSH_MAX_COUNT, "number of elements in the block", &nb) || MshEnd(c, s, "number of elements in the block")) return 1;
    if (!(t = MshTypeOf(c, type))) return 1;
    if (t->dim != dim) return MshFail(c, "element block of dimension %ld holds %d-node %ss (dimension %d)", dim, t->nnodes, t->shape, t->dim);
    if (MshEntity(c, dim, tag, "element")) return 1;
    if (nb > n - total) return MshFail(c, "element blocks hold more than the %ld elements $Elements declares (line %ld)", n, header);
    snprintf(sec, sizeof(sec), "the element block at line %ld", c->lineno);
    for (long k = 0; k < nb; ++k) {
      if (MshData(c, sec, "elements", k, nb)) return 1;
      s = c->line;
      if (MshInt(c, &s, 1, INT_MAX, "element number", &id)) return 1;
      c->ctxName = "element";
      c->ctxId   = id;
      for (int i = 0; i < t->nnodes; ++i)
        if (MshNodeRef(c, &s, t, -1, i, &idx[i])) return 1;
      if (MshEnd(c, s, "last node")) return 1;
      c->ctxName = NULL;
      if (MshAddElement(c, t, id, idx)) return 1;
      amin = id < amin ? id : amin;
      amax = id > amax ? id : amax;
    }
    total += nb;
  }
  if (MshExpectEnd(c, "$Elements", "$EndElements", nblocks, "blocks")) return 1;
  if (total != n) return MshFailAt(c, header, "$Elements declares %ld elements, but its blocks hold %ld", n, total);
  if (n && (amin != tmin || amax != tmax)) return MshFailAt(c, header, "$Elements declares element numbers from %ld to %ld, but they run from %ld to %ld", tmin, tmax, amin, amax);
  return 0;
}

/* Sections after $Elements: PETSc reads $Periodic (a periodic mesh, which the
   solver does not handle) and ignores the others; each must be closed. */
static int MshReadTrailer(MshCheck *c)
{
  char show[40], end[80];
  int  r;

  while ((r = MshNextSection(c)) > 0) {
    const char *s = MshSkip(c->line), *w;
    long        start = c->lineno;
    size_t      n;

    if (*s != '$' || !strncmp(s, "$End", 4)) return MshFail(c, "unexpected '%s' after $EndElements", MshShow(s, 0, show));
    if (MshIs(s, "$Periodic")) return MshFail(c, "periodic meshes ($Periodic) are not supported");
    for (w = s; *w && !MshSpace(*w); ++w) { }
    n = (size_t)(w - s - 1);
    if (*MshSkip(w) || n == 0 || n > 64) return MshFail(c, "malformed section marker '%s'", MshShow(s, 0, show));
    /* s points into the read buffer, which the next reads overwrite */
    snprintf(end, sizeof(end), "$End%.*s", (int)n, s + 1);
    do {
      if ((r = MshReadLine(c)) < 0) return 1;
      if (!r) return MshFailAt(c, start, "section $%s has no %s before the end of the file", end + 4, end);
    } while (!MshIs(c->line, end));
  }
  return r < 0;
}

/* The key of a face from its corners v[n] (n = 3 or 4): its three least,
   which name it in a mesh whose faces are not repeated. */
static uint64_t MshFaceKey(const int v[], int n)
{
  int s[4];

  for (int i = 0; i < n; ++i) s[i] = v[i];
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && s[j - 1] > s[j]; --j) {
      const int t = s[j];
      s[j]        = s[j - 1];
      s[j - 1]    = t;
    }
  return ((uint64_t)(uint32_t)s[0] * 0x100000001B3ULL ^ (uint64_t)(uint32_t)s[1]) * 0x100000001B3ULL + (uint64_t)(uint32_t)s[2] * 0x9E3779B97F4A7C15ULL + 1;
}

/* A 3D mesh's topology: no face shared by more than two cells, every 2D
   element a face of a cell (PETSc's reader finds each 2D element's face
   among the cells' and stops where there is none). Gmsh's corner order:
   a tetrahedron's faces are (0,1,2), (0,1,3), (0,2,3), (1,2,3); a
   hexahedron's, bottom 0-3 and top 4-7, its six sides. */
static int MshCheckSolids(MshCheck *c)
{
  static const int tf[4][4] = {{0, 1, 2, -1}, {0, 1, 3, -1}, {0, 2, 3, -1}, {1, 2, 3, -1}};
  static const int hf[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  MshHash          faces = {NULL, NULL, 0, 0, 0};
  int              fail  = 0;

  if (MshHashReserve(&faces, (size_t)(6 * c->nsolids + 16))) return MshFailAt(c, c->endElementsLine, "out of memory");
  for (long e = 0; e < c->nsolids && !fail; ++e) {
    const int *v   = c->solid + 10 * e;
    const int  hex = v[4] >= 0, nf = hex ? 6 : 4, nv = hex ? 4 : 3;
    for (int f = 0; f < nf && !fail; ++f) {
      int  w[4], *cnt;
      for (int i = 0; i < nv; ++i) w[i] = v[hex ? hf[f][i] : tf[f][i]];
      if (!(cnt = MshHashPut(&faces, MshFaceKey(w, nv)))) {
        fail = MshFailAt(c, v[9], "out of memory");
        break;
      }
      if (*cnt < 0) *cnt = 0;
      if (++*cnt > 2) fail = MshFailAt(c, v[9], "element %d: a face is shared by more than two elements (duplicate or overlapping elements)", v[8]);
    }
  }
  for (long e = 0; e < c->ncells && !fail; ++e) {
    const int *v = c->cell + 6 * e;
    if (!MshHashGet(&faces, MshFaceKey(v, v[3] < 0 ? 3 : 4))) fail = MshFailAt(c, v[5], "2D element %d is not a face of any 3D element", v[4]);
  }
  MshHashFree(&faces);
  return fail;
}

/* What PETSc's reader and the solver need of the topology: 2D elements, edges
   shared by at most two of them, line elements on their edges, point elements
   on their corners. */
static int MshCheckTopology(MshCheck *c)
{
  MshHash edges  = {NULL, NULL, 0, 0, 0};
  char   *corner = NULL;
  int     fail   = 0;

  if (c->curves && c->nsolids) {
    c->lineno  = c->solidTypeLine;
    c->ctxName = NULL;
    return MshFail3D(c, "a rigid body's mesh with %s cells: rigid bodies are 2D (curves)", c->solidType->shape);
  }
  if (c->curves) return c->nsegs ? 0 : MshFailAt(c, c->endElementsLine, "no line element in $Elements; a rigid body needs its curves");
  if (c->nsolids) return MshCheckSolids(c); /* a 3D body: its cells are one type; its 2D elements are its physical surfaces' faces */
  if (c->offPlaneLine) {
    c->lineno  = c->offPlaneLine;
    c->ctxName = NULL;
    return MshFail3D(c, "a node at z = %g, off the plane z = 0, and no 3D element", c->offPlaneZ);
  }
  if (!c->ncells) return MshFailAt(c, c->endElementsLine, "no 2D element (triangle or quadrilateral) in $Elements; the solver needs a 2D mesh");
  corner = (char *)calloc((size_t)c->nnodes, 1);
  if (!corner || MshHashReserve(&edges, (size_t)(2 * c->ncells + 16))) {
    free(corner);
    MshHashFree(&edges);
    return MshFailAt(c, c->endElementsLine, "out of memory");
  }
  for (long e = 0; e < c->ncells && !fail; ++e) {
    const int *v  = c->cell + 6 * e;
    const int  nv = v[3] < 0 ? 3 : 4;

    for (int k = 0; k < nv; ++k) {
      const int a = v[k], b = v[(k + 1) % nv];
      int      *cnt;

      corner[a] = 1;
      if (!(cnt = MshHashPut(&edges, MshHashKey(a < b ? a : b, a < b ? b : a)))) {
        fail = MshFailAt(c, v[5], "out of memory");
        break;
      }
      if (*cnt < 0) *cnt = 0;
      if (++*cnt > 2) {
        fail = MshFailAt(c, v[5], "element %d: edge from node %d to node %d is shared by more than two elements (duplicate or overlapping elements)", v[4], MshNodeTag(c, a), MshNodeTag(c, b));
        break;
      }
    }
  }
  for (long e = 0; e < c->nsegs && !fail; ++e) {
    const int *v = c->seg + 4 * e;
    if (!MshHashGet(&edges, MshHashKey(v[0] < v[1] ? v[0] : v[1], v[0] < v[1] ? v[1] : v[0]))) fail = MshFailAt(c, v[3], "line element %d (nodes %d, %d) is not an edge of any 2D element", v[2], MshNodeTag(c, v[0]), MshNodeTag(c, v[1]));
  }
  for (long e = 0; e < c->npoints && !fail; ++e) {
    const int *v = c->point + 3 * e;
    if (!corner[v[0]]) fail = MshFailAt(c, v[2], "point element %d: node %d is not a corner of any 2D element", v[1], MshNodeTag(c, v[0]));
  }
  free(corner);
  MshHashFree(&edges);
  return fail;
}

/* The whole check of an open file. */
static int MshCheckAll(MshCheck *c)
{
  int r;

  if (MshReadFormat(c)) return 1;
  if ((r = MshNextSection(c)) < 0) return 1;
  if (r && MshIs(c->line, "$PhysicalNames")) {
    if (c->line[0] != '$') return MshFail(c, "$PhysicalNames must start its line");
    if (MshReadPhysicalNames(c)) return 1;
    if ((r = MshNextSection(c)) < 0) return 1;
  }
  if (c->format == 41) {
    char show[40];
    if (!r) return MshFailAt(c, c->lineno + 1, "end of file where $Entities was expected");
    if (!MshIs(c->line, "$Entities")) return MshFail(c, "expected $Entities (PETSc's reader takes $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements in this order), found '%s'", MshShow(c->line, 0, show));
    if (MshReadEntities(c) || MshExpectSection(c, "$Nodes", "$EndEntities") || MshReadNodes41(c)) return 1;
  } else {
    char show[40];
    if (!r) return MshFailAt(c, c->lineno + 1, "end of file where $Nodes was expected");
    if (!MshIs(c->line, "$Nodes")) return MshFail(c, "expected $Nodes (PETSc's reader takes $MeshFormat, $PhysicalNames, $Nodes, $Elements in this order), found '%s'", MshShow(c->line, 0, show));
    if (MshReadNodes22(c)) return 1;
  }
  if (MshExpectSection(c, "$Elements", "$EndNodes")) return 1;
  if (c->format == 41 ? MshReadElements41(c) : MshReadElements22(c)) return 1;
  c->endElementsLine = c->lineno;
  if (MshReadTrailer(c)) return 1;
  return MshCheckTopology(c);
}

/* Runs the check on this process; returns the verdict, the message in msg. */
static MshVerdict MshCheckPath(const char path[], int curves, char msg[], size_t msglen, long *nnodes, long *nelems, int *format)
{
  MshCheck c;

  memset(&c, 0, sizeof(c));
  c.curves = curves;
  c.path   = path;
  c.msg    = msg;
  c.msglen = msglen;
  c.fp     = fopen(path, "rb");
  if (!c.fp) {
    snprintf(msg, msglen, "cannot open mesh file %s: %s", path, strerror(errno));
    return MSH_OPEN;
  }
  c.buf = (char *)malloc(MSH_BUF_LEN + 1);
  if (c.buf) (void)MshCheckAll(&c);
  else {
    snprintf(msg, msglen, "mesh %s: out of memory", path);
    c.verdict = MSH_BAD;
  }
  *nnodes = c.nnodes;
  *nelems = c.nelems;
  *format = c.format;
  fclose(c.fp);
  free(c.buf);
  free(c.node);
  free(c.nodeMap);
  free(c.stamp);
  free(c.cell);
  free(c.solid);
  free(c.seg);
  free(c.point);
  MshHashFree(&c.nodes);
  MshHashFree(&c.entities);
  return c.verdict;
}

/* Checks the file on rank 0 and raises the verdict on every rank; a 3D mesh
   is named as such, with the body. */
static PetscErrorCode MeshCheck(MPI_Comm comm, const char body[], const char path[], int curves)
{
  PetscMPIInt rank;
  int         verdict = MSH_OK;
  char        msg[MSH_MSG_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    long           nnodes = 0, nelems = 0;
    int            format = 0;
    PetscLogDouble t0, t1;

    PetscCall(PetscTime(&t0));
    verdict = (int)MshCheckPath(path, curves, msg, sizeof(msg), &nnodes, &nelems, &format);
    PetscCall(PetscTime(&t1));
    if (verdict == MSH_OK) PetscCall(PetscInfo(NULL, "Mesh %s (MSH %d.%d): %ld nodes, %ld elements, checked in %g s\n", path, format / 10, format % 10, nnodes, nelems, (double)(t1 - t0)));
  }
  PetscCallMPI(MPI_Bcast(&verdict, 1, MPI_INT, 0, comm));
  if (verdict != MSH_OK) PetscCallMPI(MPI_Bcast(msg, sizeof(msg), MPI_CHAR, 0, comm));
  PetscCheck(verdict != MSH_3D, comm, PETSC_ERR_USER_INPUT, "body %s: %s: a 2D body is a section in the plane z = 0 (plane strain, or with -axisymmetric a meridian section); a 3D body's .geo has a Volume, meshed by Tet10 or Hex27 cells", body, msg);
  PetscCheck(verdict != MSH_OPEN, comm, PETSC_ERR_FILE_OPEN, "%s", msg);
  PetscCheck(verdict != MSH_READ, comm, PETSC_ERR_FILE_READ, "%s", msg);
  PetscCheck(verdict == MSH_OK, comm, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  PetscFunctionReturn(0);
}

PetscErrorCode MeshCheckFile(MPI_Comm comm, const char body[], const char path[])
{
  PetscFunctionBeginUser;
  PetscCall(MeshCheck(comm, body, path, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode MeshCheckCurvesFile(MPI_Comm comm, const char body[], const char path[])
{
  PetscFunctionBeginUser;
  PetscCall(MeshCheck(comm, body, path, 1));
  PetscFunctionReturn(0);
}
