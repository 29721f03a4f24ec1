//! The physical primitives' settings ([`Tuning`]).

use behavior_motion::PlanParams;

/// The physical primitives' settings: how far above things hands approach and let go, how long
/// they close and wait, how hard the motion planners try, when a driven base counts as there.
/// [`Tuning::default`] is what every result of this project was measured with (most values are
/// the original's, each field says which); a study of the primitives themselves changes them
/// through [`crate::run_with`] or [`crate::Solver::with_tuning`]. Symbolic primitives do not
/// read it.
///
/// ```
/// use behavior_planning::Tuning;
///
/// // Hands that close for longer and let go from lower down.
/// let tuning = Tuning { close_steps: 80, place_height: 0.05, ..Tuning::default() };
/// assert_eq!(tuning.release_steps, Tuning::default().release_steps);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Tuning {
    /// The random offset of a grasp's approach across the object's top, m (the original's
    /// ±0.025).
    pub grasp_jitter: f32,
    /// How far in from the sides of an object's box its grasp point lies, at most, m.
    pub grasp_inset: f32,
    /// The most steps a hand closes for (the original closes for 50).
    pub close_steps: u32,
    /// How far above a sampled pose the held object is let go, m (the original's 0.1).
    pub place_height: f32,
    /// Poses sampled for a placement until a hand can get there.
    pub place_tries: usize,
    /// The most steps a hand opens for (the original's 100).
    pub release_steps: u32,
    /// Steps for a placed object to fall and settle (the original's 100).
    pub settle_steps: u32,
    /// Posed hands: how far above the top of the object's box the grasp's approach ends, m
    /// (the original's 0.05).
    pub approach_height: f32,
    /// Posed hands: one step of the descent onto the object, m.
    pub descent_step: f32,
    /// Posed hands: the most steps of descent from the approach (the original's 25), more from
    /// a raised approach.
    pub descent_steps: u32,
    /// Posed hands: headings tried for the approach until one is free and within reach.
    pub grasp_headings: usize,
    /// Posed hands: how far the body may go down to reach low things, m (its capsule's bottom
    /// is 0.2 m above the floor at the original's standing height).
    pub crouch: f32,
    /// Posed hands: how far the body may go up to reach high things, m (the BehaviorRobot's
    /// body floats; a person in VR stands up or stretches).
    pub rise: f32,
    /// Jointed arms: how far above the top of the object's box the fingertips stop before the
    /// descent, m.
    pub arm_approach: f32,
    /// Jointed arms: the longest descent onto the object, m.
    pub arm_descent: f32,
    /// Steps the robot has to reach each configuration of a densified path before the
    /// execution is given up as blocked.
    pub steps_per_waypoint: u32,
    /// How close to a base configuration counts as there, m.
    pub position_tolerance: f32,
    /// How close to a base configuration's heading counts as there, rad.
    pub yaw_tolerance: f32,
    /// The motion planners' budget (base, hands, arms): 25 times the original's iterations
    /// and ten times its shortcuts. The original's 20 × 3 found no base path for 297 of the
    /// 447 stands `bench plan` tried where 500 iterations found more (README, "Base plans and
    /// drives"); a robot carrying a board through a door, or a hand reaching round a shelf's
    /// edge, needs them, and a driven path's every wiggle costs steps (20 shortcuts left 380
    /// rad of turning in a 9 m drive). The lattice's search keeps its 25,000 nodes
    /// ([`PlanParams::expansions`]); one that runs out of them ends NAVIGATE_TO.
    pub budget: PlanParams,
    /// Places to stand tried in turn for one NAVIGATE_TO, each with a base plan there.
    pub stand_plans: u64,
}

impl Default for Tuning {
    fn default() -> Self {
        Tuning {
            grasp_jitter: 0.025,
            grasp_inset: 0.05,
            close_steps: 50,
            place_height: 0.1,
            place_tries: 20,
            release_steps: 100,
            settle_steps: 100,
            approach_height: 0.05,
            descent_step: 0.005,
            descent_steps: 25,
            grasp_headings: 8,
            crouch: 0.19,
            rise: 0.4,
            arm_approach: 0.05,
            arm_descent: 0.12,
            steps_per_waypoint: 10,
            position_tolerance: 0.01,
            yaw_tolerance: 0.02,
            budget: PlanParams {
                iterations: 500,
                restarts: 2,
                smoothing: 200,
                seed: 0,
                expansions: 25_000,
            },
            stand_plans: 3,
        }
    }
}
