//! TEMPORARY naive stand-in with the HDT API (lead's development only; replaced by the
//! helper's HDT at merge). Not committed.
#![allow(dead_code)]

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum ForestChange {
    Link { e: u32, a: u32, b: u32 },
    Cut { e: u32, a: u32, b: u32 },
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct HdtStats {
    pub(crate) promotions: u64,
    pub(crate) searches: u64,
    pub(crate) max_level: u32,
}

pub(crate) struct Hdt {
    adj: Vec<Vec<u32>>,
    ends: Vec<[u32; 2]>,
    live: Vec<bool>,
    tree: Vec<bool>,
    stats: HdtStats,
}

impl Hdt {
    pub(crate) fn new(n: usize) -> Self {
        Hdt {
            adj: vec![Vec::new(); n],
            ends: Vec::new(),
            live: Vec::new(),
            tree: Vec::new(),
            stats: HdtStats::default(),
        }
    }
    fn comp(&self, a: u32, treeonly: bool) -> Vec<bool> {
        let mut seen = vec![false; self.adj.len()];
        let mut st = vec![a];
        seen[a as usize] = true;
        while let Some(x) = st.pop() {
            for &e in &self.adj[x as usize] {
                if treeonly && !self.tree[e as usize] {
                    continue;
                }
                let [p, q] = self.ends[e as usize];
                let y = if p == x { q } else { p };
                if !seen[y as usize] {
                    seen[y as usize] = true;
                    st.push(y);
                }
            }
        }
        seen
    }
    pub(crate) fn insert(&mut self, e: u32, a: u32, b: u32, changes: &mut Vec<ForestChange>) {
        let i = e as usize;
        if self.ends.len() <= i {
            self.ends.resize(i + 1, [0, 0]);
            self.live.resize(i + 1, false);
            self.tree.resize(i + 1, false);
        }
        let t = !self.comp(a, true)[b as usize];
        self.ends[i] = [a, b];
        self.live[i] = true;
        self.tree[i] = t;
        self.adj[a as usize].push(e);
        self.adj[b as usize].push(e);
        if t {
            changes.push(ForestChange::Link { e, a, b });
        }
    }
    pub(crate) fn delete(&mut self, e: u32, changes: &mut Vec<ForestChange>) {
        let i = e as usize;
        let [a, b] = self.ends[i];
        self.live[i] = false;
        self.adj[a as usize].retain(|&f| f != e);
        self.adj[b as usize].retain(|&f| f != e);
        if !self.tree[i] {
            return;
        }
        self.tree[i] = false;
        changes.push(ForestChange::Cut { e, a, b });
        self.stats.searches += 1;
        let side = self.comp(a, true);
        for x in 0..self.adj.len() {
            if !side[x] {
                continue;
            }
            for &f in &self.adj[x] {
                let [p, q] = self.ends[f as usize];
                if !self.tree[f as usize] && side[p as usize] != side[q as usize] {
                    self.tree[f as usize] = true;
                    changes.push(ForestChange::Link { e: f, a: p, b: q });
                    return;
                }
            }
        }
    }
    pub(crate) fn connected(&mut self, a: u32, b: u32) -> bool {
        self.comp(a, true)[b as usize]
    }
    pub(crate) fn is_tree_edge(&self, e: u32) -> bool {
        self.tree.get(e as usize).copied().unwrap_or(false) && self.live[e as usize]
    }
    pub(crate) fn stats(&self) -> HdtStats {
        self.stats
    }
}
