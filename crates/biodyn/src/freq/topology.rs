//! How a body's links connect its segments, and which solver that allows.
//!
//! Parallel links between the same two ends add (springs and dampers in
//! parallel sum), and links with k = c = 0 carry nothing, so both are merged
//! or dropped first. With the seat as one node, the remaining links over
//! segments + seat form a tree exactly when there are as many of them as
//! segments (the body is connected: `Body::validate`). A tree is eliminated
//! from the leaves in O(n) per frequency (`freq::tree`); a graph with a loop
//! is reordered by reverse Cuthill–McKee and solved as a band (`freq::banded`),
//! O(n·b²) per frequency for half-bandwidth b.

use crate::body::model::{Body, End};
use std::collections::{BTreeMap, VecDeque};

/// A merged link between segments `a` < `b`, or between segment `a` and the seat.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Edge {
    pub a: usize,
    /// `None`: the seat.
    pub b: Option<usize>,
    pub k: f64,
    pub c: f64,
}

/// The merged links of a body.
#[derive(Debug, Clone)]
pub struct Graph {
    pub n: usize,
    pub edges: Vec<Edge>,
}

impl Graph {
    /// Merges parallel links and drops empty ones.
    pub fn of(body: &Body) -> Graph {
        let mut pairs: BTreeMap<(usize, usize), (f64, f64)> = BTreeMap::new();
        let mut seat: BTreeMap<usize, (f64, f64)> = BTreeMap::new();
        for l in &body.links {
            if l.k <= 0.0 && l.c <= 0.0 {
                continue;
            }
            let slot = match l.lower {
                End::Segment(j) => pairs.entry((l.upper.min(j), l.upper.max(j))).or_default(),
                End::Seat => seat.entry(l.upper).or_default(),
            };
            slot.0 += l.k;
            slot.1 += l.c;
        }
        let mut edges: Vec<Edge> = seat
            .into_iter()
            .map(|(a, (k, c))| Edge { a, b: None, k, c })
            .collect();
        edges.extend(pairs.into_iter().map(|((a, b), (k, c))| Edge {
            a,
            b: Some(b),
            k,
            c,
        }));
        Graph { n: body.n(), edges }
    }

    /// True when the merged links form a tree over segments + seat.
    pub fn is_tree(&self) -> bool {
        self.edges.len() == self.n && self.connected()
    }

    /// Every segment reaches the seat (guaranteed for a validated body).
    fn connected(&self) -> bool {
        let adj = self.adjacency(true);
        let seat = self.n;
        let mut seen = vec![false; self.n + 1];
        let mut queue = VecDeque::from([seat]);
        seen[seat] = true;
        while let Some(u) = queue.pop_front() {
            for &v in &adj[u] {
                if !seen[v] {
                    seen[v] = true;
                    queue.push_back(v);
                }
            }
        }
        seen.iter().all(|&s| s)
    }

    /// Neighbour lists; with `with_seat` the seat is node `n`.
    pub fn adjacency(&self, with_seat: bool) -> Vec<Vec<usize>> {
        let mut adj = vec![Vec::new(); self.n + usize::from(with_seat)];
        for e in &self.edges {
            match e.b {
                Some(b) => {
                    adj[e.a].push(b);
                    adj[b].push(e.a);
                }
                None if with_seat => {
                    adj[e.a].push(self.n);
                    adj[self.n].push(e.a);
                }
                None => {}
            }
        }
        adj
    }

    /// Reverse Cuthill–McKee order of the segments (seat left out) and the
    /// half-bandwidth it gives: `order[p]` is the segment at position p.
    pub fn rcm(&self) -> (Vec<usize>, usize) {
        let adj = self.adjacency(false);
        let n = self.n;
        let degree: Vec<usize> = adj.iter().map(Vec::len).collect();
        let mut seen = vec![false; n];
        let mut order = Vec::with_capacity(n);
        let mut by_degree: Vec<usize> = (0..n).collect();
        by_degree.sort_by_key(|&i| (degree[i], i));
        for &start in &by_degree {
            if seen[start] {
                continue;
            }
            // Start each component at a pseudo-peripheral node: the last
            // one reached by a BFS from its lowest-degree node.
            let root = self.far_end(&adj, &degree, start);
            seen[root] = true;
            let mut queue = VecDeque::from([root]);
            while let Some(u) = queue.pop_front() {
                order.push(u);
                let mut next: Vec<usize> = adj[u].iter().copied().filter(|&v| !seen[v]).collect();
                next.sort_by_key(|&v| (degree[v], v));
                next.dedup();
                for v in next {
                    seen[v] = true;
                    queue.push_back(v);
                }
            }
        }
        order.reverse();
        let mut pos = vec![0; n];
        for (p, &i) in order.iter().enumerate() {
            pos[i] = p;
        }
        let band = self
            .edges
            .iter()
            .filter_map(|e| e.b.map(|b| pos[e.a].abs_diff(pos[b])))
            .max()
            .unwrap_or(0);
        (order, band)
    }

    fn far_end(&self, adj: &[Vec<usize>], degree: &[usize], start: usize) -> usize {
        let mut seen = vec![false; self.n];
        let mut queue = VecDeque::from([start]);
        seen[start] = true;
        let mut last = start;
        while let Some(u) = queue.pop_front() {
            last = u;
            let mut next: Vec<usize> = adj[u].iter().copied().filter(|&v| !seen[v]).collect();
            next.sort_by_key(|&v| (degree[v], v));
            next.dedup();
            for v in next {
                seen[v] = true;
                queue.push_back(v);
            }
        }
        last
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::{Link, Segment};

    fn body(n: usize, links: Vec<Link>) -> Body {
        Body {
            segments: (0..n)
                .map(|i| Segment::new(&format!("s{i}"), 1.0))
                .collect(),
            links,
            head: 0,
            body_mass: None,
            seat: None,
        }
    }

    #[test]
    fn parallel_links_merge_and_empty_links_drop() {
        let b = body(
            2,
            vec![
                Link::new("a", 0, End::Segment(1), 1.0, 2.0),
                Link::new("b", 1, End::Segment(0), 3.0, 4.0),
                Link::new("c", 1, End::Seat, 5.0, 0.0),
                Link::new("d", 1, End::Seat, 1.0, 1.0),
                Link::new("e", 0, End::Seat, 0.0, 0.0),
            ],
        );
        let g = Graph::of(&b);
        assert_eq!(g.edges.len(), 2);
        assert!(g.edges.contains(&Edge {
            a: 0,
            b: Some(1),
            k: 4.0,
            c: 6.0
        }));
        assert!(g.edges.contains(&Edge {
            a: 1,
            b: None,
            k: 6.0,
            c: 1.0
        }));
        assert!(g.is_tree());
    }

    #[test]
    fn a_second_seat_link_makes_a_loop() {
        let mut links: Vec<Link> = (0..4)
            .map(|i| Link::new(&format!("l{i}"), i, End::Segment(i + 1), 1.0, 1.0))
            .collect();
        links.push(Link::new("seat", 4, End::Seat, 1.0, 1.0));
        assert!(Graph::of(&body(5, links.clone())).is_tree());
        links.push(Link::new("seat2", 0, End::Seat, 1.0, 1.0));
        let g = Graph::of(&body(5, links));
        assert!(!g.is_tree());
        // A chain reorders to half-bandwidth 1.
        assert_eq!(g.rcm().1, 1);
    }

    #[test]
    fn rcm_narrows_a_ring() {
        // A ring 0-1-...-19-0 numbered so that the natural order is wide.
        let n = 20;
        let perm: Vec<usize> = (0..n).map(|i| (i * 7) % n).collect();
        let mut links: Vec<Link> = (0..n)
            .map(|i| {
                Link::new(
                    &format!("r{i}"),
                    perm[i],
                    End::Segment(perm[(i + 1) % n]),
                    1.0,
                    1.0,
                )
            })
            .collect();
        links.push(Link::new("seat", 0, End::Seat, 1.0, 1.0));
        let g = Graph::of(&body(n, links));
        let (order, band) = g.rcm();
        let mut sorted = order.clone();
        sorted.sort();
        assert_eq!(sorted, (0..n).collect::<Vec<_>>());
        assert!(band <= 2, "{band}");
    }
}
