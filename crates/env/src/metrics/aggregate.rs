//! The benchmark protocol's summary over episodes (BEHAVIOR's
//! `behavior/benchmark/behavior_benchmark.py`) and the human-normalized metrics.
//!
//! The summary: Success Score (mean final Q), Success Score Top 5 (the mean of the five best
//! per-activity mean Qs), and the means of simulated time, kinematic disarrangement (relative),
//! logical disarrangement, distance navigated and displacement of hands (left + right).
//!
//! Human-normalized metrics: the paper reports each efficiency metric relative to the best human
//! demonstration of the same activity and instance. The original code has no implementation
//! (BEHAVIOR's `behavior/benchmark/behavior_benchmark.py`), so ours is: agent value / best
//! (smallest) human value, per metric, where the demonstrations' values come from the same metric
//! code run on their recordings. 1 is as efficient as the best person; 2 twice as wasteful. A
//! metric whose best human value is 0 is 1 when the agent's is 0 too and undefined (`None`)
//! otherwise. Where no person did that instance, [`HumanReference::normalize_by_activity`] compares
//! with the best person on any
//! instance of the activity, and says so.
//!
//! Per-activity statistics of the demonstrations ([`HumanStatistics`]): how many, how many
//! succeeded, their mean length, and the episode limit the original derives from it (twice the
//! mean).

use super::EpisodeMetrics;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The benchmark's aggregated metrics.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Aggregate {
    /// Episodes summarized.
    pub episodes: usize,
    /// Mean final Q.
    pub success_score: f64,
    /// Mean of the five best per-activity mean Qs (of all, with fewer than five activities).
    pub success_score_top5: f64,
    /// Mean simulated time, s.
    pub simulated_time: f64,
    /// Mean relative kinematic disarrangement, m.
    pub kinematic_disarrangement: f64,
    /// Mean logical disarrangement.
    pub logical_disarrangement: f64,
    /// Mean distance navigated, m.
    pub distance_navigated: f64,
    /// Mean displacement of both hands while touching or holding, m.
    pub displacement_of_hands: f64,
}

fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    if n == 0 { 0.0 } else { sum / n as f64 }
}

/// Summarizes episodes, each with its activity's name, as the benchmark protocol does.
pub fn aggregate(episodes: &[(String, EpisodeMetrics)]) -> Aggregate {
    let mut by_activity: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
    for (activity, m) in episodes {
        by_activity.entry(activity).or_default().push(m.q_final);
    }
    let mut activity_means: Vec<f64> = by_activity
        .values()
        .map(|qs| mean(qs.iter().copied()))
        .collect();
    activity_means.sort_by(|a, b| b.total_cmp(a));
    let all = || episodes.iter().map(|(_, m)| m);
    Aggregate {
        episodes: episodes.len(),
        success_score: mean(all().map(|m| m.q_final)),
        success_score_top5: mean(activity_means.iter().take(5).copied()),
        simulated_time: mean(all().map(|m| m.sim_time_s)),
        kinematic_disarrangement: mean(all().map(|m| m.kinematic_disarrangement)),
        logical_disarrangement: mean(all().map(|m| f64::from(m.logical_disarrangement))),
        distance_navigated: mean(all().map(|m| m.distance_navigated)),
        displacement_of_hands: mean(
            all().map(|m| m.hand_displacement_left + m.hand_displacement_right),
        ),
    }
}

/// The efficiency metrics relative to the best person (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Normalized {
    /// Simulated time.
    pub simulated_time: Option<f64>,
    /// Kinematic disarrangement.
    pub kinematic_disarrangement: Option<f64>,
    /// Logical disarrangement.
    pub logical_disarrangement: Option<f64>,
    /// Distance navigated.
    pub distance_navigated: Option<f64>,
    /// Displacement of hands.
    pub displacement_of_hands: Option<f64>,
}

/// The five efficiency metrics of an episode, in [`Normalized`]'s order.
fn efficiency(m: &EpisodeMetrics) -> [f64; 5] {
    [
        m.sim_time_s,
        m.kinematic_disarrangement,
        f64::from(m.logical_disarrangement),
        m.distance_navigated,
        m.hand_displacement_left + m.hand_displacement_right,
    ]
}

/// The best (smallest) human value of each efficiency metric, per activity and instance.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct HumanReference {
    /// Activity → instance → the best values.
    best: BTreeMap<String, BTreeMap<String, [f64; 5]>>,
    /// Activity → each demonstration's (steps, success).
    episodes: BTreeMap<String, Vec<(u32, bool)>>,
}

/// What the demonstrations of one activity say about it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HumanStatistics {
    /// Demonstrations of the activity.
    pub demonstrations: usize,
    /// How many ended with the goal holding.
    pub successes: usize,
    /// Their mean length, action steps.
    pub mean_steps: f64,
    /// The episode limit the original sets from them: twice the mean, rounded up, steps.
    pub step_limit: u32,
}

impl HumanReference {
    /// An empty reference.
    pub fn new() -> HumanReference {
        HumanReference::default()
    }

    /// Adds a human demonstration's metrics for an activity and instance (any label: a saved
    /// instance's file name, the original's instance id).
    pub fn add(&mut self, activity: &str, instance: &str, human: &EpisodeMetrics) {
        self.episodes
            .entry(activity.to_string())
            .or_default()
            .push((human.steps, human.success));
        let values = efficiency(human);
        self.best
            .entry(activity.to_string())
            .or_default()
            .entry(instance.to_string())
            .and_modify(|best| {
                for (b, v) in best.iter_mut().zip(values) {
                    *b = b.min(v);
                }
            })
            .or_insert(values);
    }

    /// An agent's episode relative to the best person on the same activity and instance;
    /// `None` without a demonstration of it.
    pub fn normalize(
        &self,
        activity: &str,
        instance: &str,
        agent: &EpisodeMetrics,
    ) -> Option<Normalized> {
        Some(relative(self.best.get(activity)?.get(instance)?, agent))
    }

    /// An agent's episode relative to the best person on any instance of the activity (each
    /// metric's smallest human value over them); `None` without a demonstration of it.
    pub fn normalize_by_activity(
        &self,
        activity: &str,
        agent: &EpisodeMetrics,
    ) -> Option<Normalized> {
        let instances = self.best.get(activity)?;
        let best = instances
            .values()
            .fold([f64::INFINITY; 5], |mut best, values| {
                for (b, v) in best.iter_mut().zip(values) {
                    *b = b.min(*v);
                }
                best
            });
        (!instances.is_empty()).then(|| relative(&best, agent))
    }

    /// The demonstrations' statistics for an activity; `None` without one.
    pub fn statistics(&self, activity: &str) -> Option<HumanStatistics> {
        let episodes = self.episodes.get(activity).filter(|e| !e.is_empty())?;
        let mean_steps = mean(episodes.iter().map(|(steps, _)| f64::from(*steps)));
        Some(HumanStatistics {
            demonstrations: episodes.len(),
            successes: episodes.iter().filter(|(_, success)| *success).count(),
            mean_steps,
            step_limit: (2.0 * mean_steps).ceil() as u32,
        })
    }
}

/// Each efficiency metric of `agent` over the best human value `best` (see the module docs).
fn relative(best: &[f64; 5], agent: &EpisodeMetrics) -> Normalized {
    let ratio = |k: usize| {
        let (a, h) = (efficiency(agent)[k], best[k]);
        match (a, h) {
            (a, h) if h > 0.0 => Some(a / h),
            (0.0, _) => Some(1.0),
            _ => None,
        }
    };
    Normalized {
        simulated_time: ratio(0),
        kinematic_disarrangement: ratio(1),
        logical_disarrangement: ratio(2),
        distance_navigated: ratio(3),
        displacement_of_hands: ratio(4),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn episode(q: f64, time: f64, hands: (f64, f64)) -> EpisodeMetrics {
        EpisodeMetrics {
            q_final: q,
            sim_time_s: time,
            kinematic_disarrangement: 2.0 * time,
            logical_disarrangement: 3,
            distance_navigated: 10.0,
            hand_displacement_left: hands.0,
            hand_displacement_right: hands.1,
            ..EpisodeMetrics::default()
        }
    }

    #[test]
    fn the_summary_is_the_benchmark_protocol_s() {
        let mut episodes = Vec::new();
        // Six activities with mean Q 0.6, 0.5, 0.4, 0.3, 0.2 and 0.1; the first has two episodes.
        episodes.push(("a0".to_string(), episode(0.8, 10.0, (1.0, 0.0))));
        episodes.push(("a0".to_string(), episode(0.4, 20.0, (0.0, 1.0))));
        for (k, q) in [0.5, 0.4, 0.3, 0.2, 0.1].into_iter().enumerate() {
            episodes.push((format!("a{}", k + 1), episode(q, 30.0, (0.5, 0.5))));
        }
        let s = aggregate(&episodes);
        assert_eq!(s.episodes, 7);
        assert!((s.success_score - 2.7 / 7.0).abs() < 1e-12);
        assert!((s.success_score_top5 - (0.6 + 0.5 + 0.4 + 0.3 + 0.2) / 5.0).abs() < 1e-12);
        assert!((s.simulated_time - 180.0 / 7.0).abs() < 1e-12);
        assert!((s.kinematic_disarrangement - 360.0 / 7.0).abs() < 1e-12);
        assert_eq!(s.logical_disarrangement, 3.0);
        assert_eq!(s.distance_navigated, 10.0);
        assert_eq!(s.displacement_of_hands, 1.0);
    }

    #[test]
    fn metrics_are_normalized_by_the_best_person_on_that_instance() {
        let mut humans = HumanReference::new();
        humans.add("a", "0", &episode(1.0, 40.0, (2.0, 0.0)));
        humans.add("a", "0", &episode(1.0, 30.0, (3.0, 1.0)));
        let agent = episode(0.5, 60.0, (4.0, 2.0));
        let n = humans.normalize("a", "0", &agent).unwrap();
        assert_eq!(n.simulated_time, Some(2.0), "60 s against the best 30 s");
        assert_eq!(n.kinematic_disarrangement, Some(2.0));
        assert_eq!(n.logical_disarrangement, Some(1.0));
        assert_eq!(n.distance_navigated, Some(1.0));
        assert_eq!(
            n.displacement_of_hands,
            Some(3.0),
            "6 m against the best 2 m"
        );
        assert_eq!(humans.normalize("a", "1", &agent), None);
        let mut still = HumanReference::new();
        still.add("b", "0", &episode(1.0, 10.0, (0.0, 0.0)));
        let n = still
            .normalize("b", "0", &episode(1.0, 10.0, (0.0, 0.0)))
            .unwrap();
        assert_eq!(n.displacement_of_hands, Some(1.0));
        let n = still
            .normalize("b", "0", &episode(1.0, 10.0, (1.0, 0.0)))
            .unwrap();
        assert_eq!(n.displacement_of_hands, None);
    }

    #[test]
    fn without_that_instance_the_best_person_on_any_instance_is_the_reference() {
        let mut humans = HumanReference::new();
        let mut quick = episode(1.0, 30.0, (3.0, 0.0));
        quick.steps = 900;
        quick.success = true;
        let mut tidy = episode(0.5, 60.0, (1.0, 0.0));
        tidy.steps = 1800;
        humans.add("a", "0", &quick);
        humans.add("a", "1", &tidy);
        let agent = episode(0.5, 90.0, (2.0, 0.0));
        let n = humans.normalize_by_activity("a", &agent).unwrap();
        assert_eq!(
            n.simulated_time,
            Some(3.0),
            "90 s against 30 s on instance 0"
        );
        assert_eq!(
            n.displacement_of_hands,
            Some(2.0),
            "2 m against 1 m on instance 1"
        );
        assert_eq!(humans.normalize_by_activity("b", &agent), None);
        let stats = humans.statistics("a").unwrap();
        assert_eq!((stats.demonstrations, stats.successes), (2, 1));
        assert_eq!(stats.mean_steps, 1350.0);
        assert_eq!(
            stats.step_limit, 2700,
            "twice the mean, as the original's limit"
        );
        assert_eq!(humans.statistics("b"), None);
    }
}
