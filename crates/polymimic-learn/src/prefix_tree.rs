//! Behaviours' primitive sequences as a tree of shared beginnings: behaviours grown from one
//! another start alike, so a decision that chains every behaviour's primitives can predict each
//! shared beginning once.

use polymimic_types::Primitive;

/// One primitive after the beginning its parent stands for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PrefixNode {
    /// The primitive this node adds (none for the root, the empty beginning).
    pub primitive: Option<Primitive>,
    pub children: Vec<usize>,
    /// The behaviours whose sequence is exactly this beginning.
    pub ending: Vec<usize>,
    /// Every behaviour whose sequence starts with it (this node's and its descendants').
    pub below: Vec<usize>,
}

/// The tree; node 0 is the root.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PrefixTree {
    pub nodes: Vec<PrefixNode>,
}

impl PrefixTree {
    /// The tree of `sequences` (behaviour i's primitives are `sequences[i]`); children keep the
    /// order their primitive first appears in.
    pub(crate) fn new<'a>(sequences: impl Iterator<Item = &'a [Primitive]>) -> Self {
        let node = |primitive| PrefixNode { primitive, children: Vec::new(), ending: Vec::new(), below: Vec::new() };
        let mut nodes = vec![node(None)];
        for (behaviour, sequence) in sequences.enumerate() {
            let mut at = 0;
            nodes[0].below.push(behaviour);
            for &primitive in sequence {
                let found = nodes[at].children.iter().copied().find(|&c| nodes[c].primitive == Some(primitive));
                at = found.unwrap_or_else(|| {
                    nodes.push(node(Some(primitive)));
                    let new = nodes.len() - 1;
                    nodes[at].children.push(new);
                    new
                });
                nodes[at].below.push(behaviour);
            }
            nodes[at].ending.push(behaviour);
        }
        Self { nodes }
    }
}

#[cfg(test)]
mod tests {
    use Primitive::{Forward as F, Left as L, Right as R};

    use super::*;

    #[test]
    fn shared_beginnings_are_one_node_and_every_behaviour_is_found_where_it_ends() {
        let sequences: [&[Primitive]; 5] = [&[F, F, L], &[F, F], &[L], &[F, R], &[]];
        let tree = PrefixTree::new(sequences.into_iter());
        // root, F, FF, FFL, L, FR
        assert_eq!(tree.nodes.len(), 6);
        assert_eq!(tree.nodes[0].ending, vec![4], "the empty sequence ends at the root");
        assert_eq!(tree.nodes[0].below, vec![0, 1, 2, 3, 4]);
        let f = tree.nodes[0].children[0];
        assert_eq!(tree.nodes[f].primitive, Some(F));
        assert_eq!(tree.nodes[f].below, vec![0, 1, 3]);
        assert!(tree.nodes[f].ending.is_empty());
        let ff = tree.nodes[f].children[0];
        assert_eq!((tree.nodes[ff].ending.clone(), tree.nodes[ff].below.clone()), (vec![1], vec![0, 1]));
        // Walking each behaviour's sequence down the tree ends at a node naming it.
        for (b, sequence) in sequences.iter().enumerate() {
            let mut at = 0;
            for &p in *sequence {
                at = tree.nodes[at].children.iter().copied().find(|&c| tree.nodes[c].primitive == Some(p)).unwrap();
            }
            assert!(tree.nodes[at].ending.contains(&b));
        }
    }
}
