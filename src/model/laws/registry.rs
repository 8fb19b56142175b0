//! The registry of contact laws: [`ModelKind`] and one [`LawInfo`] line a
//! law ([`LAWS`]: its name, its table code, its label). A leaf: the
//! parameters, the table format, the figures and every front end read it,
//! and it reads nothing of theirs.

/// Which surface friction model to evaluate: which single-asperity
/// contact law the surface integrals use (one line each in [`LAWS`],
/// docs/ARCHITECTURE.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum ModelKind {
    /// Kogut & Etsion (2004), MODEL.md §4.
    #[default]
    KogutEtsion,
    /// The CEB-type comparison model, an approximate reconstruction of
    /// Chang, Etsion & Bogy (1988) in the same statistical framework
    /// (MODEL.md §8). Its adhesion term is the Kogut–Etsion one; the
    /// [`Fit`](crate::Fit) setting does not apply to it.
    CebType,
}

crate::named!(ModelKind, "model", registry = LAWS);

impl ModelKind {
    /// The law's registry entry (name, table code, label): read by the
    /// table writer and the figures.
    #[cfg(any(feature = "builder", feature = "plot", test))]
    pub(crate) const fn law(self) -> LawInfo {
        LAWS[self as usize]
    }

    /// The value stored as `code` in a table file's header, if any.
    pub(crate) fn from_code(code: u8) -> Option<ModelKind> {
        LAWS.iter().find(|l| l.code == code).map(|l| l.kind)
    }
}

/// One law's registry entry: what front ends, tables and figures call it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LawInfo {
    /// The variant of [`ModelKind`] (the registry is in the enum's order).
    pub kind: ModelKind,
    /// The name users type and read (`--model`, JSON, the bindings).
    pub name: &'static str,
    /// The model code stored in a table file's header (never reuse one).
    pub code: u8,
    /// The curve label in the comparison figures.
    pub label: &'static str,
}

/// Every law, in the order of [`ModelKind`]'s variants (checked at
/// compile time by `named!`).
#[rustfmt::skip]
pub const LAWS: [LawInfo; 2] = [
    LawInfo { kind: ModelKind::KogutEtsion, name: "ke", code: 0, label: "Kogut–Etsion" },
    LawInfo { kind: ModelKind::CebType, name: "ceb", code: 1, label: "CEB-type (approx.)" },
];
