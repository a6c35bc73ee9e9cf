/* JSON numbers as the summaries write them. */
#include "contact.h"

void ContactJSONReal(FILE *fp, PetscReal v)
{
  if (PetscIsInfOrNanReal(v)) fprintf(fp, "null");
  else fprintf(fp, "%.17g", (double)v);
}

void ContactJSONKeyReal(FILE *fp, const char sep[], const char key[], PetscReal v)
{
  fprintf(fp, "%s\"%s\": ", sep, key);
  ContactJSONReal(fp, v);
}

void ContactJSONKeyVector(FILE *fp, const char sep[], const char key[], PetscInt n, const PetscReal v[])
{
  fprintf(fp, "%s\"%s\": [", sep, key);
  for (PetscInt k = 0; k < n; ++k) {
    if (k) fprintf(fp, ", ");
    ContactJSONReal(fp, v[k]);
  }
  fprintf(fp, "]");
}

void ContactJSONKeyPair(FILE *fp, const char sep[], const char key[], const PetscReal v[2])
{
  fprintf(fp, "%s\"%s\": [", sep, key);
  ContactJSONReal(fp, v[0]);
  fprintf(fp, ", ");
  ContactJSONReal(fp, v[1]);
  fprintf(fp, "]");
}
