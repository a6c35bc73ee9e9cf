#pragma once
/* The problem's data (problemtypes.c names its enumerations): its
   configuration (config.h), schedule, force controls and results, and the
   Problem struct that joins them. problem.c (the assembled system), the solver's files above it
   (staging.c, lmvm.c, forcesolve.c, forceouter.c, newtonstep.c, solve.c)
   and below it (forcecontrol.c, forceborder.c, the preconditioners) read
   these types; each calls only the files below it. */
#include "energyterm.h"
#include "subdomain.h"
#include "unheld.h"
#include "configtypes.h"

#define CONTACT_MAX_TERMS    16

/* The force control types by name (-force_control_type: coupled, outer):
   read by ForceControlOptionsSetFromOptions, filled by ForceControlRegisterAll (forcesolve.c). */
extern PetscFunctionList ForceControlList;

/* A force-controlled component (forcecontrol.c): body, Dirichlet condition
   and component (an index into its comps), its force, and the displacement
   and reaction of the last solve. */
typedef struct {
  PetscInt  body, bc, c;
  PetscReal force, U, R;
  PetscReal L;     /* the body's size: its reference bounding box's diagonal */
  PetscReal scale; /* what |R - force| is measured against: |force| and the body's loads */
  PetscBool anchor; /* the anchor of a body held by contact (anchors.c): force 0 */
  PetscReal kref;   /* an anchor: a motion stiffer than this is held by the contact (forceborder.c) */
  PetscBool motion; /* unknown c (x, y, or the arc L theta) of rigid body `body`'s motion (rigidbody.h): no stiffness of its own, its border the contact's at each Hessian; bc: its condition, or -1 */
} ForceControl;

/* Force control's state (forcecontrol.c): the controlled components, and
   for the coupled type the border of the Hessian, the frozen directions of
   the anchors and the Newton step's solve of H inside the bordered one. */
typedef struct {
  PetscInt     n;                       /* the controlled components, anchors included */
  ForceControl c[CONTACT_MAX_CONTROLS];
  PetscBool    coupled;                 /* the controls' displacements are the last entries of X */
  Vec          B[CONTACT_MAX_CONTROLS]; /* coupled: K_fc 1 of each control (Xb's layout); a rigid body's unknown: the contact's coupling, at each Hessian */
  PetscReal    D[CONTACT_MAX_CONTROLS * CONTACT_MAX_CONTROLS]; /* coupled: 1^T K_cc 1 between controls; a rigid body's unknowns: the contact's J^T H J, at each Hessian */
  Vec          E[CONTACT_MAX_CONTROLS]; /* coupled, a control on a body whose tangent varies: e_k, its body's local vector (1 on its group's component), kept for its column at each Hessian */
  PetscBool    rigid;                   /* some control is a rigid body's unknown: the border changes with the Hessian */
  Unheld       unheld; /* coupled: the anchors' directions the contact does not hold (unheld.c) */
  KSP          ksp;    /* coupled, Newton: the solve of H inside the bordered one (newtonstep.c) */
} ForceControls;

/* -load_path: the staged solve's converged loads, from rest (staging.c):
   each one's load factor, energy Pi (the bodies' and the terms', the loads'
   potential included) and the reaction of every Dirichlet group (the bodies'
   groups in order, two components each). */
typedef struct {
  PetscInt   n, cap, ngroups;
  PetscReal *load, *energy, *reaction; /* [cap], [cap], [cap][ngroups][3] */
} LoadPath;

/* -load_stages: the converged state at the end of each stage (staging.c),
   and its figures (the driver's, after the solve): the energy, every
   Dirichlet group's reaction (as LoadPath's) and each term's contact force. */
typedef struct {
  PetscInt  n;                           /* the stages whose end is recorded (1..n) */
  Vec       X[CONTACT_MAX_STAGES];       /* X at each stage's end */
  PetscReal reaction[CONTACT_MAX_STAGES][3 * CONTACT_MAX_BODIES * CONTACT_MAX_BC]; /* three components a group (x, y, z) */
  PetscReal force[CONTACT_MAX_STAGES][CONTACT_MAX_TERMS][2];
} StageEnds;

/* What a solve and its post-processing found. */
typedef struct {
  PetscInt           nEnergyEvals, nHessianEvals, iterations; /* iterations: TAO's, over all stages */
  PetscInt           stagesDone, cutbacks; /* the stages solved, and how many times the load was cut back */
  PetscInt           lagSolves; /* friction: the fixed points' lag updates, one per converged solve of an increment */
  PetscReal          loadDone;             /* the load parameter of the last converged stage (0..-load_stages) */
  PetscReal          load;                 /* the load parameter the bodies are at (ProblemSetLoad) */
  TaoConvergedReason reason;
  PetscReal          energy, gnorm;        /* at the solution (ProblemPostProcess) */
  PetscReal          contactForceNorm;     /* ||f_c||, the contacts' nodal forces at the solution (forcestop.c; 0: none) */
  PetscReal          bodyEnergy[CONTACT_MAX_BODIES]; /* each body's elastic energy at the solution */
  PetscReal          taylorRates[2], taylorRemainders[2][8], taylorEps[8]; /* ProblemTaylorTest */
  PetscInt           taylorN;
  PetscInt           controlSolves; /* force control: the solves of its outer iteration */
  PetscInt           h0Refreshes;   /* -lmvm_h0 contact: the H0 set-ups (the first included) */
  PetscInt           pairsDropped;  /* -lmvm_pair_ratio: the correction pairs dropped */
  PetscInt           lmvmRestarts;  /* -lmvm_restarts: the L-BFGS solves restarted */
  PetscInt           decrementSolves; /* -lmvm_decrement_rtol: the H0 solves of the decrement test */
  PetscInt           decrementFloor;  /* -lmvm_decrement_rtol: last stages ended at the decrement's round-off floor */
  char               why[256];      /* why the solve stopped short, if the problem itself knows ("" else) */
  LoadPath           path;          /* -load_path */
  StageEnds          ends;          /* -load_stages */
} ProblemResults;

/* What the solve runs (staging.c), written by schedule.c alone: the
   options' load steps, penalty continuation and decrement test, or, where
   the user gave none, what the program chose (ProblemSetPenaltyContinuation,
   ProblemSetDecrementTest); force control's solves from a converged state
   run one stage (ProblemScheduleOneStage). */
typedef struct {
  PetscInt  loadSteps, penaltyStages;
  PetscReal penaltyStart;  /* the first stage's k_p over the scene's */
  PetscReal decrementRtol; /* the last stage stops on the decrement (0: on the gradient tolerances; -1: not chosen yet) */
} ProblemSchedule;

/* -stop_force_rtol (forcestop.c): the final stop also asks the gradient to be
   small against the forces the contacts carry. */
typedef struct {
  PetscBool          active;    /* the coming TAO solves stop at the final tolerance: the test applies */
  PetscBool          met;       /* the gradient tolerance was met in the current TaoSolve, at Xmet */
  Vec                Xmet;      /* the iterate of least gradient since (kept while the solve goes on) */
  TaoConvergedReason metReason; /* the reason TAO's test gave there */
  PetscInt           continued; /* TAO solves that went on past the gradient tolerance */
  PetscInt           fallbacks; /* of those, ended at Xmet after a later stop that was not a convergence */
  PetscInt           floors;    /* of those, ended where the gradient stalled (its round-off floor) */
  PetscInt           stalled;   /* iterations since the gradient last halved, past TAO's test */
  PetscReal          best;      /* the least gradient norm past TAO's test (Xmet's) */
  PetscReal          ref;       /* the gradient norm the next must halve (reset where it does) */
  PetscReal          ratio;     /* the last test's ||g|| / ||f_c|| (-1: none) */
} ForceStop;

/* The watch for a frictional contact that slides without end (slidewatch.c):
   the largest trial slip of the last iterates while no node sticks. */
typedef struct {
  PetscInt  n;       /* iterates recorded (the last three kept) */
  PetscReal slip[3]; /* their largest trial slips, oldest first */
  PetscInt  growing; /* consecutive iterates whose slip grew without contracting */
  PetscInt  peak;    /* the most of them in the current TAO solve */
  PetscInt  term;    /* the pair it watched last (-1: none) */
  PetscBool sliding; /* no node of some frictional pair sticks at the last iterate */
  PetscInt  stops;   /* solves it stopped */
  PetscReal bound;   /* a slip beyond this is no displacement's: twice the largest one imposed */
} SlideWatch;

/* The whole scene: bodies joined into one vector, energy terms, TAO glue.
   L-BFGS's state lives with the TAO solver that uses it (lmvm.c). */
typedef struct _n_Problem *Problem;
struct _n_Problem {
  MPI_Comm       comm;
  SolverConfig   cfg; /* what the options say (config.h) */
  ProblemSchedule sched;
  PetscInt       nbodies;
  Body           bodies[CONTACT_MAX_BODIES];
  PetscInt       nterms;
  EnergyTerm     terms[CONTACT_MAX_TERMS];
  PetscInt       offset[CONTACT_MAX_BODIES]; /* start of each body in this rank's part of X */
  Vec            X, G; /* TAO's unknowns and gradient: the bodies' dofs, then (coupled force control, rank 0) the controlled displacements */
  Vec            Xb;   /* the bodies' dofs alone, the layout of K and H (X itself without coupled controls) */
  Vec            X0;   /* the first iterate (NULL: rest; ignored with load or penalty stages) */
  Mat            H, K; /* Hessian, elastic stiffness of the bodies */
  IS             surfaceDofs; /* contact-surface dofs (the contact Hessian's block), or NULL */
  PetscBool      hessianGrown; /* a term's Hessian left K's pattern (its own, 3D): H starts from Kh since */
  Mat            Kh;           /* after a growth: K laid out in H's pattern, copied into H as it stands (or NULL) */
  PetscObjectState khState;    /* H's nonzero state when Kh was laid out: H grown again lays it out anew */
  Subdomain      sub;         /* several ranks: this rank's cells and their stiffness, until the Newton step takes it */
  Tao            tao;
  PetscBool      exactHessian; /* the second-order term is in the current Hessian (may be indefinite) */
  PetscReal      hessianG0;    /* -contact_hessian auto: the ||g|| its switch is relative to (ProblemSetHessianSwitchReference) */
  PetscBool      tangentAuto;  /* Newton's step chooses per Hessian between K and a neohookean body's tangent (tangentswitch.c) */
  PetscBool      tangentFull;  /* the current Hessian has the tangent (tangentAuto: its choice) */
  PetscBool      tangentForce; /* the tangent whatever the iteration (the Taylor test) */
  PetscBool      tangentSlow;  /* tangentAuto: the modified steps have converged slowly in this solve */
  PetscReal      tangentG[3];  /* tangentAuto: the gradient norms of the last three iterations */
  ForceControls  fc;        /* force control (forcecontrol.c) */
  ForceStop      fstop;     /* -stop_force_rtol (forcestop.c) */
  SlideWatch     slide;     /* slidewatch.c */
  Mat            Htao;      /* the Hessian TAO sees: H, or H bordered by the controls (forceborder.c) */
  ProblemResults res;
};

