/**
 * The slicer's floating-point tolerances, each named once: what it absorbs, and its unit. The values are the
 * ones the code has always used, and the G-code depends on them bit for bit. Each name stands for one meaning;
 * the same length in two units has two names (1e-9 mm is 1e-6 µm, yet 1e-9 × 1000 is not 1e-6 in floating
 * point, so each is written as it is used).
 *
 * Sizes below which a feature is not printed (the smallest loop, the thinnest strip) are not tolerances: they
 * stay with the stage that drops the feature.
 */

// ---------------------------------------------------------------------------------------------------------
// Whole numbers from quotients

/**
 * A quotient of two settings rounded to a whole number (walls in a wall thickness, layers in a Z gap, a line
 * width's share of another, scarf steps along a length, minutes left) is taken as the whole number it lies
 * within this of, so that float division neither adds one nor drops one (0.3 / 0.1 is 2.9999999999999996).
 * Dimensionless.
 */
export const WHOLE_QUOTIENT_EPS = 1e-9;

/**
 * A thickness within this share of a layer of a whole number of layers is that many layers, as
 * ceil(t / h − LAYER_SHARE_EPS): skin and Z thicknesses typed in mm do not divide by layer heights exactly.
 * Layers.
 */
export const LAYER_SHARE_EPS = 1e-6;

// ---------------------------------------------------------------------------------------------------------
// Lengths, positions, directions

/**
 * Lengths compared in mm (a footprint inside the bed, clear of another, nearer than another spot; a Z gap
 * under half a layer) are equal within this. mm.
 */
export const LENGTH_EPS_MM = 1e-9;

/**
 * The same length in µm: lengths compared in µm (a Z gap against layer middles) are equal within it, and a
 * distance no longer than it is no distance (it has no direction to follow). µm.
 */
export const LENGTH_EPS_UM = 1e-6;

/**
 * Parameters along a segment (0 at its start, 1 at its end): a crossing within this of an end is at the end,
 * and two crossings this close are one. Dimensionless.
 */
export const SEGMENT_T_EPS = 1e-9;

/** Two unit vectors whose cosine is within this of −1 point opposite ways. Dimensionless. */
export const OPPOSITE_COS_EPS = 1e-9;

/** Two unit directions whose cross product (the sine between them) is under this are parallel. Dimensionless. */
export const PARALLEL_SIN_EPS = 1e-6;

/**
 * The orientation vote of a chain of slice segments starts this far forward, so that a loop whose segments'
 * votes cancel exactly keeps the direction it was chained in. µm (the slice's coordinates).
 */
export const VOTE_TIE_UM = 1e-9;

// ---------------------------------------------------------------------------------------------------------
// Divisors kept from zero

/** The least time left for a layer's extrusions when they are slowed for the minimum layer time, s. */
export const MIN_TIME_S = 1e-6;

/** The least angle a corner's arc speed limit divides by (Marlin's junction deviation), radians. */
export const MIN_ANGLE_RAD = 1e-9;

/** The sagitta an arc fit tries in place of a straight line (a sagitta of 0, whose radius is infinite), mm. */
export const MIN_SAGITTA_MM = 1e-9;

/** The least infill density a pattern's spacing divides by, as a fraction of solid. */
export const MIN_DENSITY = 1e-6;

// ---------------------------------------------------------------------------------------------------------
// The firmware's own

/**
 * Marlin's planner as modelled: a move shorter than this over X, Y and Z moves the extruder only, and one
 * shorter than this in all is no move. mm.
 */
export const MARLIN_MIN_MOVE_MM = 1e-6;

/** Klipper's toolhead: a move shorter than this over X, Y and Z moves the extruder only (its `move_d < .000000001`). mm. */
export const KLIPPER_MIN_MOVE_MM = 1e-9;

/** G-code templates compare numbers equal within this (`{if layerZ == 0.2}`). Dimensionless. */
export const TEMPLATE_NUMBER_EPS = 1e-9;
