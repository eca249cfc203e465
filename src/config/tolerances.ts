// Every tolerance and work cap of the simulation, each with what it guards. Geometry is in px, time in s.
// Changing one changes outcomes: the tests pin their consequences (tests/stability.test.ts,
// tests/systems/collisions.test.ts).

/** Returned for "no such event" times and distances: far beyond any simulated time, yet finite. */
export const NEVER = 1e300

/** Largest relative disagreement accepted between a given GRAVITY and V_SKIP_MAX (one derives the other). */
export const CONSISTENCY_TOLERANCE = 1e-9

/** Contact is declared when the gap is at most this, px, and the balls approach. */
export const GAP_TOLERANCE = 1e-7
/**
 * Balls approach when the gap closes faster than this share of their relative speed plus SETTLE_FLOOR of
 * BALL_SETTLE_SPEED: rounding after a contact that left them sliding side by side is not a new contact,
 * and balls settled against each other (their speeds equal to within 1e-5 of the settle speed) stay
 * settled instead of averaging their velocities ever more finely. A pair that closes slower than that is
 * not a contact until it is SINK_DEPTH deep: it sinks into itself by up to SETTLE_FLOOR · BALL_SETTLE_SPEED
 * px a second until then. At 1e-3, a light ball lying against a heavy one that a third ball nudged toward it
 * at 8e-4 px/s was 1e-3 px deep 0.67 s later (the long adversarial run at 71×).
 */
export const APPROACH_EPSILON = 1e-9
export const SETTLE_FLOOR = 1e-5
/**
 * Depth, px, past which two balls that close at all are a contact (exact method), however slowly: a pair that
 * closes slower than SETTLE_FLOOR · BALL_SETTLE_SPEED sinks into itself no deeper than this (it sank on without
 * end: 1e-3 px about 110 s after two balls met closing at 9e-6 px/s), and then settles (a contact slower than
 * BALL_SETTLE_SPEED). A tenth of the overlap the adversarial suite allows, and ten seconds' sinking at the floor.
 */
export const SINK_DEPTH = 1e-4
/**
 * A contact within this time, s, of an earlier contact of either ball is elastic (the TC model of Luding and
 * McNamara): a push through a row of touching balls then passes along it in one sweep, as in Newton's
 * cradle, instead of dissipating in an endless run of ever-smaller contacts (inelastic collapse).
 */
export const CONTACT_DURATION = 1e-4
/**
 * Gap, px, within which two balls, or a ball and a wall, count as touching: when a settling contact gathers
 * its cluster, and when a settling cluster touches a wall (it leaves a wall it moves into at the
 * restitutions' product, systems/collisions.ts).
 */
export const TOUCH_GAP = 1e-6
/** Most balls one settling contact moves together. */
export const MAX_CLUSTER = 256
/** Least advance of the contact search while two balls touch without approaching, s. */
export const MIN_ADVANCE = 1e-6
/** Iterations of one contact search before it is put back in the heap to continue later. */
export const MAX_SEARCH_STEPS = 512

/** Bookkeeping events (exits, near misses) one ball may take in one pass of the integration system, each consuming a hole ahead. */
export const MAX_INLINE_EVENTS = 1 << 16

/** Below this many holes the planner scans them all (no grid to keep), and so does the overlap check of a hole being added; from it on, they use the hole grid and the holes by cell. */
export const GRID_MIN_HOLES = 32

/** Largest number of cells the hole grid may have; a sparser grid is made coarser to stay under it. */
export const MAX_GRID_CELLS = 1 << 22

/** Full spot checks the launcher makes per launch instant for held balls (each a lookup in the moving and resting grids). */
export const MAX_SPOT_CHECKS = 64

/**
 * The launcher's kicks back off: after its k-th kick with no ball launched since, it kicks again no sooner
 * than CONTACT_TICK · 2^(min(k, KICK_BACKOFF_DOUBLINGS) − 1) later (systems/launcher.ts): about 4.3 s at most
 * with the default tick.
 */
export const KICK_BACKOFF_DOUBLINGS = 10

/**
 * A moving ball whose swept capsule would cover more grid cells than this in a step (a very large or very
 * fast ball) is not rasterised into the contact hash: it is paired with every moving ball near it directly,
 * and every other prediction pairs with it directly. Bounds a prediction's work for a ball of any radius.
 */
export const MAX_CAPSULE_CELLS = 1024

/** A resting ball wider than this many grid cells (radius / cell) is kept beside the resting grid, not in it. */
export const MAX_RESTING_CELLS = 4


/**
 * Fixed-tick contacts: the overlap projection sweeps over the pairs until no overlap is deeper than
 * PROJECTION_SLOP px (a jammed pile needs many sweeps: each moves a push one ball further through it). Full
 * sweeps first; once a sweep moves fewer balls than an eighth of the pairs, sweeps over the pairs of the balls
 * still moving (src/contacts/fixedPairs.ts). A tick's projection visits at most PROJECTION_BUDGET × pairs
 * pairs, in at most MAX_LISTED_SWEEPS sweeps, and queues again at most PROJECTION_QUEUE_BUDGET × pairs pairs
 * of the balls its pushes moved (each push reads every pair of both its balls: in a crowd where every ball
 * touches eighty others, that was 160 pairs a visit, 5,378 × pairs a tick and 0.2 s a tick on a machine 3.5×
 * slower than the development machine; the piles pressed by a stream, 2,500 and 10,000 balls with e = 0 and
 * e = 1, and a jammed 17 × 17 box queue at most 218 × pairs a tick, so they never reach it).
 */
export const PROJECTION_BUDGET = 64
export const PROJECTION_QUEUE_BUDGET = 1024
export const MAX_LISTED_SWEEPS = 1024
export const PROJECTION_SLOP = 1e-4
/** Least share of a pair's overlap each ball takes in the projection, whatever the mass ratio (positions only: no momentum or energy is involved). */
export const MIN_PROJECTION_SHARE = 0.1

/**
 * Fixed-tick contacts: a tick whose pairs outnumber TICK_PAIRS_PER_CANDIDATE a candidate is halved as many
 * times (up to MAX_TICK_HALVINGS, a tick of CONTACT_TICK / 1,024) as makes the least work over its span
 * (src/contacts/fixedHalve.ts): where the balls cover many of their spacings a tick, each paired with every
 * ball it could reach. Coarsened again once a tick's pairs are within a quarter of the bound. Piles, a gas at
 * area fraction 0.2 and the panel's bursts have a few pairs a candidate at most; thousands of radius-0.5
 * balls at 3e4 px/s in a 1,000 px box have hundreds at 1/120 s.
 */
export const TICK_PAIRS_PER_CANDIDATE = 16
export const MAX_TICK_HALVINGS = 10
/**
 * Fixed-tick contacts with restitution above 0: a tick is halved, up to config.CONTACT_TRAVEL_HALVINGS times
 * from CONTACT_TICK, until at most TRAVEL_SHARE of the candidates that have a pair have a nearest partner
 * (least gap) closing more than TRAVEL_PER_TICK of the two radii a tick (src/contacts/fixedTravel.ts). A
 * ball that covers its partner's size in a tick meets it again within the same tick, and past
 * RESTITUTION_VISITS visits such a pair closes inelastically: 200 radius-11 balls at 3,000 px/s in an
 * elastic 420 × 480 box keep 0.07 of their energy over 2 s at 1/120 s without this rule, 0.96-0.996 with it,
 * as at a CONTACT_TICK of 1/960 s (seeds 1-5). The tick is not coarsened back while the coarser one would
 * have more than half that share: at a share of 0.25 the spacing went back and forth, and kept 0.81-0.985.
 */
export const TRAVEL_PER_TICK = 0.5
export const TRAVEL_SHARE = 0.1
/**
 * Fixed-tick contacts: a tick's pairs are counted as they will be at its end when every one of the last
 * GROWTH_TICKS ticks ended with more than it gathered, by the least of those growths (src/contacts/fixedHalve.ts):
 * a crowd whose solve keeps speeding balls up past their reach. A push along a row grows its pairs at a tick or
 * two, not at each of four.
 */
export const GROWTH_TICKS = 4
/**
 * Fixed-tick contacts: relative gap below which a step's end and a contact tick are the same instant (a few
 * ulps: a clock summed from 1/120 s steps drifts from k·(1/120)); the step then ends at the tick, solved
 * (src/contacts/fixedHalve.ts, nearTick).
 */
export const TICK_SNAP = 8 * Number.EPSILON
/**
 * Fixed-tick contacts: rounds a tick of widening the reach of balls the solve sped up (src/contacts/fixedReach.ts);
 * each carries a push one ball further along a row with gaps. After MAX_WIDEN_ROUNDS the rounds go on, up
 * to MAX_PASS_ROUNDS, only while a ball sped up beyond its reach moves more in a tick than its radius and
 * the smallest candidate's together, the distance at which it could pass a ball it was not paired with
 * instead of ending inside it, where the next tick's projection would take it out; or while the last round
 * added pairs and the tick has at most CHAIN_PAIRS_PER_BALL pairs a candidate (a push along a row: left
 * unpaired at the row's end, the last ball was pushed into by the projection, and passed, at 300 px/s); or
 * when a round added no pair but widened a ball moving into a closed wall within the tick, once a tick, in a
 * tick of at most CHAIN_PAIRS_PER_BALL pairs a candidate (solved once more, so the wall sends it back at the tick, not
 * between ticks back through the row).
 */
export const MAX_WIDEN_ROUNDS = 4
export const MAX_PASS_ROUNDS = 256
/**
 * ... and past MAX_PASS_ROUNDS, up to MAX_CHAIN_ROUNDS, while the tick has at most CHAIN_PAIRS_PER_BALL
 * pairs a candidate: a push running along a row of balls with gaps (each ball paired with the next one
 * its capsule meets, src/contacts/fixedCapsule.ts), not a crowd, whose rounds each cost its many pairs. A
 * row of 2,000 radius-0.5 balls 1 px apart struck end on at 1e5 px/s needs about 830 rounds in its first
 * tick; at 256 the ball at index 258 went through its neighbour.
 */
export const MAX_CHAIN_ROUNDS = 4096
export const CHAIN_PAIRS_PER_BALL = 4
/**
 * ... and past MAX_CHAIN_ROUNDS, up to CHAIN_ROUNDS_PER_CANDIDATE rounds a candidate, while each solve
 * call keeps the stamps of the one before (src/contacts/fixedCalls.ts): a round then costs the few balls
 * it changes and the cells it looks up, not the tick's candidates. A row of 5,000 radius-0.5 balls 1 px
 * apart struck at 1e5 px/s let the ball at index 4,098 through its neighbour at MAX_CHAIN_ROUNDS.
 */
export const CHAIN_ROUNDS_PER_CANDIDATE = 2
/**
 * The rounds after MAX_WIDEN_ROUNDS stop once the tick has PASS_PAIRS_PER_BALL pairs a candidate, or the
 * last round paired each ball it widened with more than PASS_PAIRS_PER_WIDENED balls. A ball widened by
 * its whole travel in every direction is paired with every ball within it: rows of tiny balls side by
 * side struck at 1e5 px/s added tens of thousands of pairs a round (20 rows of 200 balls of radius 0.5,
 * 4 px apart: 7.2 million pairs by the 50th round without these bounds). Such a ball is now widened along
 * its path (CAPSULE_TRAVEL), a row's length of pairs. A bound of 64 pairs a candidate alone cut single
 * rows short: a ball went through a row of 250 radius-0.5 balls from the 82nd at 5e4 px/s.
 */
export const PASS_PAIRS_PER_BALL = 256
/**
 * ... and when they stop there (or at PASS_PAIRS_PER_WIDENED) with a ball that could still pass another,
 * the tick's solve is dropped and the tick solved again, halved once more than the try before, then 3, 7
 * and 15 times more (src/contacts/fixedRedo.ts), at most MAX_TICK_REDOS times and never past
 * MAX_TICK_HALVINGS: a ball 100 times heavier than a row of radius-0.5 balls 1 px apart, striking it at
 * 1e5 px/s, sends each light ball ahead at nearly twice its speed, every light ball then reaches every
 * other within the tick, and balls went through others from index 501 of 520 (604 of 1,000).
 */
export const MAX_TICK_REDOS = 4
/**
 * A try that leaves a pair closing deep into itself, or a ball near a closed wall still moving into it, that
 * a finer spacing would solve (src/contacts/fixedDeep.ts) is solved again halved on a tick of at most
 * CHAIN_PAIRS_PER_BALL pairs a candidate, and on a tick of more only when it leaves at most DEEP_FRONTS of
 * them (counted together) and had at most CHAIN_PAIRS_PER_BALL pairs a candidate before its widening rounds.
 * A push along a row leaves its front and the wall ahead: the first tick of a mass-3 ball striking 55
 * radius-0.5 balls 2 px apart at 3,000–1e4 px/s has 10–20 pairs a candidate after its rounds and one or two
 * of them, and was not solved again, so a ball passed its neighbour before the next tick. A crowd whose balls
 * cover their spacing in a tick leaves many: of the 248 such ticks of a burst of heavy balls at 1e5 px/s in
 * a closed elastic box (the long adversarial run's), 241 left five or more, and every try there costs the
 * whole crowd. A crowd squeezed in a box narrower than a ball has its pairs from its radii before any round:
 * solved again at a finer spacing, it kept that spacing (too many pairs to coarsen back), 17 s of stepping
 * for a sequence of 0.5 s (a named test in tests/adversarial.test.ts).
 */
export const DEEP_FRONTS = 2
/**
 * Fixed-tick contacts: a pair whose smaller ball is a speck (radius under this, under a px across) closes deep
 * (src/contacts/fixedDeep.ts) only when the speck's centre would come more than this far inside the other
 * ball, or a quarter of the other's radius if less, rather than its own radius: half a px inside a ball is not
 * seen. For balls of radius 0.5 px and more nothing changes.
 */
export const DEEP_UNSEEN_DEPTH = 0.5
/**
 * ... but a tick of at most SMALL_TICK_BALLS candidates is solved again halved however many pairs it has:
 * a try costs little there. Twelve balls in a closed elastic box, some at 2e4–1e5 px/s, all paired with
 * all after the first tick's rounds: the solve left two closing on straight lines 26 px into each other
 * before the next tick, and they went through each other between the ticks (6 and 10 of 200 such scenes
 * of 3–12 balls on two seeds, seen every 1/3,840 s; none solved again so; of 33–60 balls, 27 of 120 with
 * this at 32, 5 at 64; 64 fast balls in a box cost 2.2× the step time at 1e5 px/s, 1.1× at 3e4).
 */
export const SMALL_TICK_BALLS = 64
/**
 * Fixed-tick contacts with restitution above 0: a tick of at most SMALL_TICK_BALLS balls, its pairs' masses all
 * within PUMP_MASS_RATIO of one another, whose solve closed a pair inelastically past RESTITUTION_VISITS though
 * the two were more than RESTITUTION_REDO_GAP px apart at the tick's start, is solved again at a finer spacing
 * (src/contacts/fixedRedo.ts), at most RESTITUTION_REDO_TRIES times: such a pair met again within the tick
 * because a third ball or a wall sent it back across its gap, and a finer tick puts those meetings in ticks of
 * their own. A ball 4 or 10 times heavier struck at 850 px/s into a 5 × 5 pile 2 px apart in the corner of a
 * closed elastic box left 0.71 and 0.48 of the energy (21 aims) without this, 0.999 and 0.994 with it. Not
 * for balls that touch (a finer tick does not part meetings at one instant, and only adds ticks at which they
 * close) nor with a far heavier ball (it drives light ones to and fro within any tick, docs/decisions.md §12):
 * with a ball 100 times heavier the touching pile kept 0.27 instead of 0.38.
 */
export const RESTITUTION_REDO_GAP = 0.1
export const RESTITUTION_REDO_TRIES = 2
/**
 * Fixed-tick contacts: as DEEP_FRONTS, for a tick that had at most one pair a candidate before its widening
 * rounds (a push along a row). At a tick of 1/1,920 s a mass-100 ball striking 120 radius-0.5 balls 0.3 px
 * apart at 3,000 px/s leaves three (the push part-way along the row, balls at its speed behind balls at
 * rest), and at 2 a ball passed its neighbour. At 4 for every tick, the long adversarial run's 1,909th
 * sequence, crowds of about four pairs a candidate leaving three or four, had 5 ticks more solved again,
 * each halving the ticks after it (627 ticks in its slow step against 389), and its run took twice as long
 * (5,371 ms dev. against 2,482: its run's budget exceeded).
 */
export const DEEP_ROW_FRONTS = 4
/**
 * Fixed-tick contacts: a ball the solve sped up so that it would move more than CAPSULE_TRAVEL times its
 * radius in a tick is widened along its path only, to the capsule it sweeps (src/contacts/fixedCapsule.ts).
 */
export const CAPSULE_TRAVEL = 4
/**
 * ... and only if its circle would be more than CAPSULE_CELLS times the tick's cell (sized by the
 * candidates' reaches): where the balls around it are about as fast, their own reaches cover about as
 * much as its circle would, and a capsule saves no pairs (2,000 radius-0.5 balls at up to 1e4 px/s in a
 * 400 px box: 333 ms a step with capsules, 295 without).
 */
export const CAPSULE_CELLS = 2
export const PASS_PAIRS_PER_WIDENED = 1024

/**
 * Fixed-tick contacts: the impulses a pair takes with its restitution in one tick; met again after that
 * within the tick, it closes inelastically (so a light ball between heavy ones is not bounced to and fro
 * without end). At 1 (once a tick) dense elastic scenes lost energy the exact method keeps: docs/decisions.md §12.
 */
export const RESTITUTION_VISITS = 4

/**
 * Fixed-tick contacts: the fewest balls of a jam the velocity sweeps leave closing that moves on as one body
 * (src/contacts/fixedJam.ts): a row of this many balls or more, joined by pairs still closing after half
 * the sweeps or met this tick, their normals along one line (ROW_LINE_COS), none able to reach a closed
 * wall, closing by more than PROJECTION_SLOP in all. Gauss-Seidel sweeps even out a chain's velocities in about the square of its
 * length; shorter chains are left to them. At 2 and 8 both of the benchmark's pressed piles and its
 * mass-mix crowd changed; at 16 only the pile with e = 0 does (its deepest overlaps no deeper), and a
 * striker of mass 10 into 300 balls 0.01 px apart (e = 0) ends with the whole row at its centre-of-mass
 * speed, as the inelastic law has it (at 64: the same, with twice the overlap on the way).
 */
export const JAM_MIN_BALLS = 16

/**
 * Fixed-tick contacts: the fewest balls of a row (every pair's normal along one line, ROW_LINE_COS) that
 * the projection, when its sweeps run out with an overlap left, takes out from one of its balls
 * (src/contacts/fixedLayered.ts). Gauss-Seidel sweeps share a push out along a chain in about the square
 * of its length: a train of 13 touching radius-11 balls driven by a ball of mass 100 (e = 0.5) was still
 * 0.005 px deep after the 64 sweeps of a tick, and 0.0028 px at a step after 0.5 s, with this at 16.
 */
export const ROW_MIN_BALLS = 3

/**
 * Fixed-tick contacts: how far the normals of a group's pairs may turn from the line of its first pair for
 * the group to count as a row, cos 30° (src/contacts/fixedJam.ts, fixedShock.ts). A row struck end on has
 * all its normals on one line, the pairs a tick's swept test finds between balls that are not neighbours
 * too (a fast striker meets a dozen balls ahead of it on straight lines); a pile has normals 60° or 90°
 * apart, and is left to the sweeps (unless, with restitution below 1, a ball SQUEEZE_MASS_RATIO times heavier
 * than another presses it: src/contacts/fixedShock.ts). The projection's pass (src/contacts/fixedLayered.ts)
 * judges a group by its pairs that touch or overlap: a train pressed within itself that the tick paired with
 * a pile apart from it is a row.
 */
export const ROW_LINE_COS = Math.sqrt(3) / 2

/**
 * Fixed-tick contacts: how many times lighter than its partner a ball must be for the pair to be solved
 * together with the closed wall the ball is driven into (src/contacts/fixedWallPair.ts, pairWithWall). Against a partner less
 * than this much heavier, the push runs down by m/(M + m) a sweep between the wall and the pair, and the
 * sweeps settle it; solved with the wall, a ball lost the part of its motion the wall would send back, and
 * an elastic gas drained (docs/decisions.md §12).
 */
export const SQUEEZE_MASS_RATIO = 3

/**
 * Exact contacts: contacts one ball may take within one contact tick of the world's clock, [k·CONTACT_TICK,
 * (k + 1)·CONTACT_TICK), before its later contacts in that tick settle (perfectly inelastic, the touching
 * cluster leaves together; the fixed tick counts them the same way: PUMP_MASS_RATIO). A light ball squeezed between heavy balls, or between a heavy ball and a wall,
 * would take about π·√(M/m) contacts (1e9 for a mass ratio of 1e18) and stop the world at the pass cap; a
 * Newton's cradle or a burst takes a few a tick. Counted on the clock, not per step (it was, and a scene
 * that reached it differed between frame rates), so a step takes at most this many contacts a ball for each
 * tick it spans.
 */
export const MAX_TICK_CONTACTS = 64

/**
 * Fixed-tick contacts: a ball past MAX_TICK_CONTACTS contacts in one contact tick of the world's clock takes its
 * later contacts in that tick without restitution against balls this many times heavier or more
 * (src/contacts/fixedCount.ts). Heavy balls pump light ones in a closed elastic box toward MAX_SPEED, each
 * bounce off a ball moving at V adding up to 2V; the contacts of balls within this ratio keep their
 * restitution: a crowd of masses 3.5e5 and 4.3e6 (a ratio of 12) lost half its energy in 0.2 s when they did
 * not.
 */
export const PUMP_MASS_RATIO = 100

/**
 * Contacts off or exact: the moving balls are put back in id order (src/world/idLists.ts, orderMoving) at a step's
 * start once more than 1 / MOVING_ORDER_CHURN of them have come and gone, in a moving set of more than
 * MOVING_ORDER_MIN balls (below it the per-ball arrays stay in cache whatever the order). Each ball out of
 * order costs the pass cache misses once the arrays are out of the caches, the ordering about 2 ns a moving
 * ball: in the dense scene (bench/dense.ts), side by side over 4 rounds, ordering at 1/16 steps 100,000
 * balls in 0.95x the time of ordering at 1/4 and 0.9x that at 1/64 (every step there); 10,000 in 1.02x
 * and 0.92x.
 */
export const MOVING_ORDER_MIN = 4096
export const MOVING_ORDER_CHURN = 16

/**
 * Contacts on: a settling contact (slower than BALL_SETTLE_SPEED) of two balls alone, sliding past each other
 * at GRAZE_SLIDE × BALL_SETTLE_SPEED or more, is a graze: the two take the normal impulse and keep their
 * tangential motion instead of leaving with their centre-of-mass velocity (which stopped two balls grazing
 * at 300 px/s each way dead). Lower, it reached into settling piles: a packed 15 × 15 pile with e = 0.3
 * took 9,942 contacts to settle at 16 (1,785 without the rule, 1,822 at 64). Not with restitution 0, where
 * the two would stay touching and creep; only at a pair's first touch, and counted toward MAX_TICK_CONTACTS
 * (pressed together again, they settle).
 */
export const GRAZE_SLIDE = 64

/**
 * Fixed-tick contacts: the work meter (src/contacts/fixedBudget.ts). A CONTACT_TICK span of the clock may
 * spend config.CONTACT_WORK_BUDGET visits to every pair of its balls, counted as at least MIN_WORK_BALLS
 * balls (config.UNLIKE_MASS_BUDGET: visits to each pair its first try pairs, counted as at least
 * MIN_WORK_BALLS' n·(n − 1)/2 pairs). Past that, the span's remaining ticks are lean: one try, one velocity call of LEAN_ITERATIONS sweeps
 * and no widening rounds, a projection of at most LEAN_PROJECTION_BUDGET × pairs pair visits (and as many
 * again after each of up to MAX_WIDEN_ROUNDS join rounds); past LEAN_SHARE × the budget more, the span's last
 * ticks are skipped.
 */
export const MIN_WORK_BALLS = 64
/**
 * The ratio of two balls' masses from which their pair's work counts toward config.UNLIKE_MASS_BUDGET, the
 * budget of a span with no CONTACT_WORK_BUDGET (src/contacts/fixedBudget.ts): a light ball between two heavy
 * ones closing takes about π·√(M/m) meetings to turn them, 314 at this ratio.
 */
export const UNLIKE_MASS_RATIO = 1e4
export const LEAN_ITERATIONS = 2
export const LEAN_PROJECTION_BUDGET = 2
export const LEAN_SHARE = 1
/**
 * Fixed-tick contacts: rounds of the tick's last guard against a pair left closing deep (src/contacts/fixedGuard.ts),
 * each a walk over the tick's pairs that closes such pairs inelastically. Of the 1,000 rows of npm run
 * bench:piston-rows, one tick needed 26 (its row passed at 16), none other more than 16; 3 ran out at 64, in
 * rows a ball 1e9 times heavier drives across its box within a tick (no number of rounds turns it there).
 */
export const GUARD_ROUNDS = 32
