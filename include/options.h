#pragma once
#include <petscsys.h>

/* Options files are read by the program, not by PETSc (options.c): before
   PetscInitialize(), on rank 0 after MPI_Init(), every "-options_file FILE" of
   the command line (and of the files themselves) is replaced by the file's
   options, in place, and the expanded command line is broadcast. A missing,
   unreadable or malformed file is then one message naming the file (and line),
   not PETSc's traceback from inside PetscInitialize(); a relative path in
   "-options_file PATH" inside a file is relative to that file's folder, and
   the source of every option is kept for ContactOptionsResolvePath(). Returns 0, or 1 with the
   message in err on every rank. The expanded arguments live until
   ContactOptionsFinalize(). */
int  ContactOptionsExpandFiles(MPI_Comm comm, int *argc, char ***argv, char err[], size_t len);
void ContactOptionsFinalize(void);
/* Before MPI_Init(): the value of the last "name" on the command line with
   its options files expanded (as ContactOptionsExpandFiles() will read it),
   for a choice that must be made before the libraries start (-blas_kernel).
   Returns 1 if given (value empty if given without one), 0 if not or if the
   files cannot be read (ContactOptionsExpandFiles() reports that later). */
int ContactOptionsPeek(int argc, char **argv, const char name[], char value[], size_t len);

/* A path option's value (option pre + opt, its value in path) resolved where
   it was given: a relative path from an options file is relative to that
   file's folder, one from the command line to the current directory. where
   (if not NULL) says so for an error message; empty for an absolute path. */
PetscErrorCode ContactOptionsResolvePath(const char pre[], const char opt[], char path[], size_t len, char where[], size_t wlen);
/* The same for an input file, which must be readable: the error names the
   option, the path looked at and what it is relative to. Collective. */
PetscErrorCode ContactOptionsGetInputFile(MPI_Comm comm, const char pre[], const char opt[], char path[], size_t len);

/* PETSc's conversion of an option's value (PetscOptionsStringToReal, ...Int,
   ...Scalar, ...Bool) fails with a message that quotes the value but not the
   option. Given the function and message of such an error, writes
   "option -NAME: 'VALUE' is not a number" (or an integer, or true/false) into
   buf and returns PETSC_TRUE; PETSC_FALSE if the error is another one or no
   option has that value. For the error handler: reads the options database,
   raises no error. */
PetscBool ContactOptionsDescribeValueError(const char fun[], const char mess[], char buf[], size_t len);

/* A real option with no default value of its own, read inside a
   PetscOptionsBegin() block like PetscOptionsReal(): deflt says what stands in
   for a default ("required", or the option it is taken from). -help shows
   "<value : deflt>" if the option is given or has (the value before the call
   means something), else "<deflt>", never the placeholder the code starts from. */
/* Whether the user gave one of TAO's gradient tolerances (-tao_gatol,
   -tao_grtol, -tao_gttol): a stop chosen, which the program's own stop
   tests (L-BFGS's decrement, the forces' test) then leave alone. */
PetscErrorCode ContactGradientToleranceGiven(PetscBool *given);
PetscErrorCode ContactOptionsRealNoDefault(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char deflt[], PetscBool has, PetscReal *value, PetscBool *set);

/* An option given without a value (followed by another option, or last on
   the command line or its line) is an error naming it, for every option that
   takes one, PETSc's and the program's: ContactOptionsExpandFiles() gives
   each such option a spelling of true, which a switch reads as given alone
   and a number or a choice cannot convert (ContactOptionsDescribeValueError
   then names the option); options whose value PETSc makes optional (viewers,
   monitors, -help, -info, -log_*) are left as given. The program's names,
   paths and lists are read with these, which stop at such a value. */
PetscErrorCode ContactOptionsString(PetscOptionItems *, const char opt[], const char text[], const char man[], const char current[], char value[], size_t len, PetscBool *set);
PetscErrorCode ContactOptionsStringArray(PetscOptionItems *, const char opt[], const char text[], const char man[], char *value[], PetscInt *n, PetscBool *set);
PetscErrorCode ContactOptionsFList(PetscOptionItems *, const char opt[], const char text[], const char man[], PetscFunctionList, const char current[], char value[], size_t len, PetscBool *set);
/* The names in list, "a, b, c", for an error that lists the known ones. */
PetscErrorCode ContactOptionsListNames(PetscFunctionList list, char known[], size_t len);
/* Whether value is the one given to an option given without a value (as
   -options_left and the unused-option check show it: without a value). */
PetscBool      ContactOptionsGivenWithoutValue(const char value[]);
