//! Each feature's statistics, per episode and over a dataset, as LeRobot keeps them for
//! normalization: `{min, max, mean, std, count, q01, q10, q50, q90, q99}`, every value a list
//! with one number per dimension (images: one per channel, shaped (3, 1, 1), on a 0–1 scale,
//! counted in frames).
//!
//! An episode's quantiles are exact (its values sorted, linear interpolation between the two
//! nearest, as numpy's default; an image channel's from its 256-bin histogram, nearest rank).
//! Over a dataset they are the episodes' weighted by frames, as LeRobot aggregates them: exact
//! quantiles would need every value of every episode at once.

use serde_json::{Value, json};

/// The quantiles kept, as (key, fraction).
const QUANTILES: [(&str, f64); 5] = [
    ("q01", 0.01),
    ("q10", 0.10),
    ("q50", 0.50),
    ("q90", 0.90),
    ("q99", 0.99),
];

/// Statistics per dimension of `rows`, each row one frame's vector.
pub(super) fn of_rows<R: Iterator<Item = f64>>(rows: impl Iterator<Item = R>) -> Value {
    let mut columns: Vec<Vec<f64>> = Vec::new();
    for row in rows {
        for (d, v) in row.enumerate() {
            if d == columns.len() {
                columns.push(Vec::new());
            }
            columns[d].push(v);
        }
    }
    if columns.is_empty() {
        return json!({"count": [0]});
    }
    let count = columns[0].len();
    let mut stats = serde_json::Map::new();
    let per_dim = |columns: &[Vec<f64>], f: &dyn Fn(&[f64]) -> f64| -> Value {
        columns.iter().map(|c| f(c)).collect::<Vec<f64>>().into()
    };
    stats.insert(
        "min".into(),
        per_dim(&columns, &|c| {
            c.iter().copied().fold(f64::INFINITY, f64::min)
        }),
    );
    stats.insert(
        "max".into(),
        per_dim(&columns, &|c| {
            c.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        }),
    );
    stats.insert("mean".into(), per_dim(&columns, &mean));
    stats.insert(
        "std".into(),
        per_dim(&columns, &|c| variance(c, mean(c)).sqrt()),
    );
    stats.insert("count".into(), json!([count]));
    for column in &mut columns {
        column.sort_by(f64::total_cmp);
    }
    for (key, q) in QUANTILES {
        stats.insert(key.into(), per_dim(&columns, &|sorted| quantile(sorted, q)));
    }
    Value::Object(stats)
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

fn variance(values: &[f64], mean: f64) -> f64 {
    values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / values.len().max(1) as f64
}

/// The `q` quantile of sorted values, interpolated linearly between the nearest two.
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let Some(last) = sorted.len().checked_sub(1) else {
        return 0.0;
    };
    let at = q * last as f64;
    let (below, frac) = (at.floor() as usize, at.fract());
    let above = (below + 1).min(last);
    sorted[below] + (sorted[above] - sorted[below]) * frac
}

/// An image feature's statistics, gathered frame by frame.
pub(super) struct ImageStats {
    /// Per channel: how many pixels had each value.
    histograms: [[u64; 256]; 3],
    /// Per channel: the sum and sum of squares of the values on a 0–1 scale.
    sums: [(f64, f64); 3],
    frames: usize,
}

impl ImageStats {
    pub fn new() -> ImageStats {
        ImageStats {
            histograms: [[0; 256]; 3],
            sums: [(0.0, 0.0); 3],
            frames: 0,
        }
    }

    /// Adds one RGB frame.
    pub fn add(&mut self, rgb: &[u8]) {
        for pixel in rgb.chunks_exact(3) {
            for (c, &v) in pixel.iter().enumerate() {
                self.histograms[c][usize::from(v)] += 1;
                let x = f64::from(v) / 255.0;
                self.sums[c].0 += x;
                self.sums[c].1 += x * x;
            }
        }
        self.frames += 1;
    }

    /// The statistics, each a list of three channels shaped (1, 1).
    pub fn finish(&self) -> Value {
        let pixels = self.histograms[0].iter().sum::<u64>().max(1) as f64;
        let channel = |f: &dyn Fn(usize) -> f64| -> Value {
            (0..3)
                .map(|c| json!([[f(c)]]))
                .collect::<Vec<Value>>()
                .into()
        };
        let first = |c: usize| self.histograms[c].iter().position(|&n| n > 0).unwrap_or(0);
        let last = |c: usize| self.histograms[c].iter().rposition(|&n| n > 0).unwrap_or(0);
        let mean = |c: usize| self.sums[c].0 / pixels;
        let mut stats = serde_json::Map::new();
        stats.insert("min".into(), channel(&|c| first(c) as f64 / 255.0));
        stats.insert("max".into(), channel(&|c| last(c) as f64 / 255.0));
        stats.insert("mean".into(), channel(&mean));
        stats.insert(
            "std".into(),
            channel(&|c| {
                (self.sums[c].1 / pixels - mean(c) * mean(c))
                    .max(0.0)
                    .sqrt()
            }),
        );
        stats.insert("count".into(), json!([self.frames]));
        for (key, q) in QUANTILES {
            stats.insert(key.into(), channel(&|c| self.quantile(c, q, pixels)));
        }
        Value::Object(stats)
    }

    /// The value at rank `q` × pixels in channel `c`'s histogram, 0–1.
    fn quantile(&self, c: usize, q: f64, pixels: f64) -> f64 {
        let rank = (q * pixels).ceil().max(1.0) as u64;
        let mut seen = 0;
        for (value, &n) in self.histograms[c].iter().enumerate() {
            seen += n;
            if seen >= rank {
                return value as f64 / 255.0;
            }
        }
        1.0
    }
}

/// One feature's statistics over episodes, as LeRobot's `aggregate_stats` makes them: min of
/// minima, max of maxima, the mean and variance of all frames (the parallel algorithm), the
/// quantiles weighted by frames.
pub(super) fn aggregate(episodes: &[&Value]) -> Value {
    let Some(first) = episodes.first() else {
        return json!({"count": [0]});
    };
    let counts: Vec<f64> = episodes
        .iter()
        .map(|s| flat(&s["count"]).first().copied().unwrap_or(0.0))
        .collect();
    let total: f64 = counts.iter().sum();
    let column = |key: &str| -> Vec<Vec<f64>> { episodes.iter().map(|s| flat(&s[key])).collect() };
    let dims = flat(&first["mean"]).len();
    let fold = |key: &str, f: fn(f64, f64) -> f64, start: f64| -> Vec<f64> {
        let values = column(key);
        (0..dims)
            .map(|d| {
                values
                    .iter()
                    .filter_map(|v| v.get(d).copied())
                    .fold(start, f)
            })
            .collect()
    };
    let weighted = |values: &[Vec<f64>]| -> Vec<f64> {
        (0..dims)
            .map(|d| {
                let sum: f64 = values
                    .iter()
                    .zip(&counts)
                    .map(|(v, n)| v.get(d).copied().unwrap_or(0.0) * n)
                    .sum();
                sum / total.max(1.0)
            })
            .collect()
    };
    let means = column("mean");
    let mean = weighted(&means);
    let spread: Vec<Vec<f64>> = means
        .iter()
        .zip(column("std"))
        .map(|(m, s)| {
            (0..dims)
                .map(|d| s[d] * s[d] + (m[d] - mean[d]) * (m[d] - mean[d]))
                .collect()
        })
        .collect();
    let std: Vec<f64> = weighted(&spread).iter().map(|v| v.sqrt()).collect();
    let shape = |values: Vec<f64>| shaped_like(&first["mean"], &values);
    let mut stats = serde_json::Map::new();
    stats.insert("min".into(), shape(fold("min", f64::min, f64::INFINITY)));
    stats.insert(
        "max".into(),
        shape(fold("max", f64::max, f64::NEG_INFINITY)),
    );
    stats.insert("mean".into(), shape(mean));
    stats.insert("std".into(), shape(std));
    stats.insert("count".into(), json!([total as u64]));
    for (key, _) in QUANTILES {
        stats.insert(key.into(), shape(weighted(&column(key))));
    }
    Value::Object(stats)
}

/// The numbers of a (nested) list, in order.
pub(super) fn flat(value: &Value) -> Vec<f64> {
    match value {
        Value::Array(items) => items.iter().flat_map(flat).collect(),
        other => other.as_f64().into_iter().collect(),
    }
}

/// `values` nested as `template` is (a list, or a list of (1, 1) lists for an image).
fn shaped_like(template: &Value, values: &[f64]) -> Value {
    let nested = template
        .as_array()
        .and_then(|a| a.first())
        .is_some_and(Value::is_array);
    if nested {
        values
            .iter()
            .map(|v| json!([[v]]))
            .collect::<Vec<Value>>()
            .into()
    } else {
        values.to_vec().into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_interpolate_between_the_nearest_values_as_numpy_does() {
        let sorted = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(quantile(&sorted, 0.5), 3.0);
        assert!((quantile(&sorted, 0.1) - 1.4).abs() < 1e-12);
        assert!((quantile(&sorted, 0.99) - 4.96).abs() < 1e-12);
        assert_eq!(quantile(&[7.0], 0.9), 7.0);
    }

    #[test]
    fn episode_statistics_are_per_dimension() {
        let rows = [[0.0, 10.0], [2.0, 30.0]];
        let stats = of_rows(rows.iter().map(|r| r.iter().copied()));
        assert_eq!(stats["min"], json!([0.0, 10.0]));
        assert_eq!(stats["max"], json!([2.0, 30.0]));
        assert_eq!(stats["mean"], json!([1.0, 20.0]));
        assert_eq!(stats["std"], json!([1.0, 10.0]));
        assert_eq!(stats["count"], json!([2]));
        assert_eq!(stats["q50"], json!([1.0, 20.0]));
    }

    #[test]
    fn aggregated_statistics_equal_those_of_all_frames_together() {
        let a = [[0.0], [2.0]];
        let b = [[4.0], [6.0], [8.0]];
        let all: Vec<[f64; 1]> = a.iter().chain(&b).copied().collect();
        let of = |rows: &[[f64; 1]]| of_rows(rows.iter().map(|r| r.iter().copied()));
        let joined = aggregate(&[&of(&a), &of(&b)]);
        let whole = of(&all);
        for key in ["min", "max", "mean", "std", "count"] {
            let (x, y) = (flat(&joined[key]), flat(&whole[key]));
            assert!((x[0] - y[0]).abs() < 1e-12, "{key}: {x:?} against {y:?}");
        }
    }

    #[test]
    fn image_statistics_are_per_channel_on_a_unit_scale() {
        let mut stats = ImageStats::new();
        stats.add(&[0, 255, 0, 0, 255, 0]);
        stats.add(&[255, 255, 0, 255, 255, 0]);
        let s = stats.finish();
        assert_eq!(s["min"], json!([[[0.0]], [[1.0]], [[0.0]]]));
        assert_eq!(s["max"], json!([[[1.0]], [[1.0]], [[0.0]]]));
        assert_eq!(s["mean"], json!([[[0.5]], [[1.0]], [[0.0]]]));
        assert_eq!(s["count"], json!([2]));
        assert_eq!(s["q10"], json!([[[0.0]], [[1.0]], [[0.0]]]));
        assert_eq!(s["q90"], json!([[[1.0]], [[1.0]], [[0.0]]]));
    }
}
