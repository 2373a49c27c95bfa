//! Parameters by name (`k4`, `pelvis-seat.k`, `mass`): how studies and
//! settings read and change one scalar of a body, validated.

use super::body::Body;
use super::error::ModelError;
use crate::body::limits::mass_in_range;
use crate::io::excerpt::quote;

/// A scalar parameter of a body that studies and settings can change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// Total body mass: rescales every segment by its share.
    BodyMass,
    /// Mass of segment i (0-based, top to bottom).
    Mass(usize),
    /// Stiffness of link i (0-based, in declaration order).
    Stiffness(usize),
    /// Damping of link i.
    Damping(usize),
}

impl Body {
    /// Rescales every segment to share × `kg`; needs a share on every segment.
    /// The body is re-validated; on error it is unchanged, and the error
    /// names the body mass (and the segment it pushed out of range).
    pub fn set_body_mass(&mut self, kg: f64) -> Result<(), ModelError> {
        if !mass_in_range(kg) {
            return Err(ModelError::BadBodyMass(kg));
        }
        // The seat's parts keep their masses: a heavier person sits on the same seat.
        if let Some(s) = self.segments.iter().find(|s| !s.seat && s.share.is_none()) {
            return Err(ModelError::NoShare(quote(&s.name)));
        }
        let mut next = self.clone();
        for s in next.segments.iter_mut().filter(|s| !s.seat) {
            s.mass = s.share.unwrap_or(0.0) * kg;
        }
        next.body_mass = Some(kg);
        next.validate()?;
        *self = next;
        Ok(())
    }

    /// Resolves a user-facing parameter name: `body_mass`, `m1`.., `k1`..,
    /// `c1`.. (numbered top to bottom), a segment name (its mass), or a link
    /// name with `.k` / `.c`.
    pub fn param(&self, name: &str) -> Result<Param, ModelError> {
        let unknown = || ModelError::UnknownParam(quote(name));
        let lower = name.trim().to_ascii_lowercase();
        if matches!(
            lower.as_str(),
            "body_mass" | "body-mass" | "mass" | "bodymass"
        ) {
            return Ok(Param::BodyMass);
        }
        if let Some(seg) = self.segments.iter().position(|s| s.name == name.trim()) {
            return Ok(Param::Mass(seg));
        }
        if let Some((link, what)) = name.trim().rsplit_once('.')
            && let Some(i) = self.links.iter().position(|l| l.name == link)
        {
            return match what {
                "k" => Ok(Param::Stiffness(i)),
                "c" => Ok(Param::Damping(i)),
                _ => Err(unknown()),
            };
        }
        // The first character may be more than one byte (`é1`): split on a char.
        let mut chars = lower.chars();
        let kind = chars.next().ok_or_else(unknown)?;
        let idx: usize = chars.as_str().parse().map_err(|_| unknown())?;
        if idx == 0 {
            return Err(unknown());
        }
        let i = idx - 1;
        match kind {
            'm' if i < self.n() => Ok(Param::Mass(i)),
            'k' if i < self.links.len() => Ok(Param::Stiffness(i)),
            'c' if i < self.links.len() => Ok(Param::Damping(i)),
            _ => Err(unknown()),
        }
    }

    /// Current value of a parameter. Body mass falls back to Σm / Σshare
    /// when it was never set explicitly, or to the seated mass without shares.
    pub fn get(&self, p: Param) -> f64 {
        match p {
            Param::BodyMass => self.body_mass.unwrap_or_else(|| self.seated_mass()),
            Param::Mass(i) => self.segments[i].mass,
            Param::Stiffness(i) => self.links[i].k,
            Param::Damping(i) => self.links[i].c,
        }
    }

    /// Sets a parameter and re-validates; on error the body is unchanged.
    pub fn set(&mut self, p: Param, value: f64) -> Result<(), ModelError> {
        let exists = match p {
            Param::BodyMass => true,
            Param::Mass(i) => i < self.n(),
            Param::Stiffness(i) | Param::Damping(i) => i < self.links.len(),
        };
        if !exists {
            return Err(ModelError::UnknownParam(self.label(p)));
        }
        let mut next = self.clone();
        match p {
            Param::BodyMass => next.set_body_mass(value)?,
            Param::Mass(i) => {
                // Checked here so the error names the mass typed, not a body mass.
                if !mass_in_range(value) {
                    return Err(ModelError::BadMass {
                        segment: quote(&next.segments[i].name),
                        value,
                    });
                }
                // Keep the share in step with a mass set by hand, so a later
                // body-mass change scales what the user sees, not the old share.
                let seg = &mut next.segments[i];
                seg.mass = value;
                if let (Some(_), Some(bm)) = (seg.share, next.body_mass) {
                    seg.share = Some(value / bm);
                }
            }
            Param::Stiffness(i) => next.links[i].k = value,
            Param::Damping(i) => next.links[i].c = value,
        }
        next.validate()?;
        *self = next;
        Ok(())
    }

    /// Short label of a parameter as the paper writes it (m1, k4, …) or "body mass".
    pub fn label(&self, p: Param) -> String {
        match p {
            Param::BodyMass => "body mass".into(),
            Param::Mass(i) => format!("m{}", i + 1),
            Param::Stiffness(i) => format!("k{}", i + 1),
            Param::Damping(i) => format!("c{}", i + 1),
        }
    }
}

impl Param {
    /// Unit of the parameter's value, for labels.
    pub fn unit(self) -> &'static str {
        match self {
            Param::BodyMass | Param::Mass(_) => "kg",
            Param::Stiffness(_) => "N/m",
            Param::Damping(_) => "N·s/m",
        }
    }
}
