#pragma once
#include "body.h"

/* The stiffness's nonzero pattern of a body, node by node (pattern.c): for
   each node of its local cells, the distinct columns its rows couple to,
   the mapped indices (map: local dof -> column, or -1 to drop) of every node
   of every cell around it, sorted. fn(ctx, dof, n, cols) is called once a
   node, dof its first component's local dof; its rows are dof + d, d < dim. */
typedef PetscErrorCode (*PatternNodeFn)(void *ctx, PetscInt dof, PetscInt n, const PetscInt cols[]);
PetscErrorCode BodyNodeColumns(Body, const PetscInt map[], PatternNodeFn fn, void *ctx);
