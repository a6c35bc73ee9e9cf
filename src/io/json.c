/* JSON numbers as the summaries write them. */
#include "contact.h"

void ContactJSONReal(FILE *fp, PetscReal v)
{
  if (PetscIsInfOrNanReal(v)) fprintf(fp, "null");
  else fprintf(fp, "%.17g", (double)v);
}
