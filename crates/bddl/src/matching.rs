//! Bipartite matching and covering over the cells of a pair quantifier (`rows × cols`).
//!
//! Weighted matching uses the Hungarian algorithm of the `pathfinding` crate, which assigns every
//! row of a `rows ≤ cols` matrix. Two standard reductions adapt it: an exact number `n` of pairs is
//! obtained with `rows − n` extra columns carrying a bonus no real choice can outweigh, and a cell
//! that may not be used carries a penalty no real choice can make up for.

use itertools::Itertools;
use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;

/// Size of a maximum matching among the cells for which `edge(row, col)` holds.
pub fn max_matching(rows: usize, cols: usize, edge: impl Fn(usize, usize) -> bool) -> usize {
    if rows == 0 || cols == 0 {
        return 0;
    }
    let (r, c, transposed) = if rows <= cols {
        (rows, cols, false)
    } else {
        (cols, rows, true)
    };
    let weights = Matrix::from_fn(r, c, |(i, j)| {
        let hit = if transposed { edge(j, i) } else { edge(i, j) };
        i64::from(hit)
    });
    // A full assignment of the smaller side that uses as many edges as possible.
    kuhn_munkres(&weights).0 as usize
}

/// The best total weight of exactly `n` disjoint pairs, with the pairs, where `weight(row, col)`
/// is `None` for a cell that cannot be used. `None` when no such `n` pairs exist.
///
/// Weights are `i128` because the optimizer packs a count of forced leaves above bit 64 of its
/// values (see [`crate::optimize`]); the reductions below stay in range for weights below
/// about 2^90 and up to thousands of rows.
pub fn best_matching(
    rows: usize,
    cols: usize,
    n: usize,
    weight: impl Fn(usize, usize) -> Option<i128>,
) -> Option<(i128, Vec<(usize, usize)>)> {
    if n == 0 {
        return Some((0, Vec::new()));
    }
    if n > rows.min(cols) {
        return None;
    }
    let transposed = rows > cols;
    let (r, c) = if transposed {
        (cols, rows)
    } else {
        (rows, cols)
    };
    let cell = |i: usize, j: usize| {
        if transposed {
            weight(j, i)
        } else {
            weight(i, j)
        }
    };
    let cells: Vec<Option<i128>> = (0..r * c).map(|k| cell(k / c, k % c)).collect();
    let largest = cells.iter().flatten().map(|w| w.abs()).max()?;
    let r128 = r as i128;
    // Using a forbidden cell costs more than any set of real cells can gain.
    let forbidden = -(2 * r128 * (largest + 1) + 1);
    // Each of the `r − n` spare columns must be used: a bonus beyond any real total.
    let spare = r - n;
    let bonus = 2 * r128 * (-forbidden) + 1;
    let matrix = Matrix::from_fn(r, c + spare, |(i, j)| {
        if j >= c {
            bonus
        } else {
            cells[i * c + j].unwrap_or(forbidden)
        }
    });
    let (_, assignment) = kuhn_munkres(&matrix);
    let mut total: i128 = 0;
    let mut pairs = Vec::with_capacity(n);
    for (i, &j) in assignment.iter().enumerate() {
        if j >= c {
            continue;
        }
        total += cells[i * c + j]?;
        pairs.push(if transposed { (j, i) } else { (i, j) });
    }
    debug_assert_eq!(pairs.len(), n);
    pairs.sort_unstable();
    Some((total, pairs))
}

/// All ways to cover `cover` of the `rows + cols` lines of the grid: each yields the uncovered cells
/// (row-major indices). Negated pair quantifiers are disjunctions over these (König's theorem).
pub fn covers(rows: usize, cols: usize, cover: usize) -> impl Iterator<Item = Vec<usize>> {
    (0..rows + cols).combinations(cover).map(move |lines| {
        let row_covered = |i: usize| lines.contains(&i);
        let col_covered = |j: usize| lines.contains(&(rows + j));
        (0..rows)
            .filter(|&i| !row_covered(i))
            .flat_map(|i| {
                (0..cols)
                    .filter(move |&j| !col_covered(j))
                    .map(move |j| i * cols + j)
            })
            .collect()
    })
}

/// All sets of `n` disjoint pairs, each as row-major cell indices.
pub fn matchings(rows: usize, cols: usize, n: usize) -> impl Iterator<Item = Vec<usize>> {
    (0..rows).combinations(n).flat_map(move |chosen_rows| {
        (0..cols).permutations(n).map(move |chosen_cols| {
            chosen_rows
                .iter()
                .zip(&chosen_cols)
                .map(|(i, j)| i * cols + j)
                .collect()
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maximum_matching_is_not_a_row_and_column_count() {
        // Every row and column has an edge, yet only two disjoint pairs exist (the reference's
        // row/column test would accept a perfect pairing here).
        let m = [
            [true, true, true],
            [true, false, false],
            [true, false, false],
        ];
        assert_eq!(max_matching(3, 3, |i, j| m[i][j]), 2);
        assert_eq!(max_matching(2, 3, |_, _| true), 2);
        assert_eq!(max_matching(3, 2, |i, j| i == 2 && j == 1), 1);
        assert_eq!(max_matching(0, 3, |_, _| true), 0);
    }

    #[test]
    fn best_matching_respects_exact_count_and_forbidden_cells() {
        let w = [[Some(5), Some(1)], [None, Some(4)], [Some(2), None]];
        assert_eq!(
            best_matching(3, 2, 2, |i, j| w[i][j]),
            Some((9, vec![(0, 0), (1, 1)]))
        );
        assert_eq!(
            best_matching(3, 2, 1, |i, j| w[i][j]),
            Some((5, vec![(0, 0)]))
        );
        // Negative weights: exactly one pair must still be chosen.
        assert_eq!(
            best_matching(2, 2, 1, |i, j| Some(-1 - (i + j) as i128)),
            Some((-1, vec![(0, 0)]))
        );
        let only_row_0 = [[Some(1), Some(1)], [None, None]];
        assert_eq!(best_matching(2, 2, 2, |i, j| only_row_0[i][j]), None);
        assert_eq!(best_matching(2, 2, 3, |_, _| Some(1)), None);
    }

    #[test]
    fn enumerations_have_the_expected_counts() {
        assert_eq!(matchings(3, 3, 2).count(), 3 * 6);
        assert_eq!(covers(2, 3, 1).count(), 5);
        assert_eq!(covers(2, 2, 1).next().unwrap(), vec![2, 3]);
    }
}
