//! An analog second-order section, the stages' common form.

use num_complex::Complex64;

/// An analog section (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²).
#[derive(Debug, Clone, Copy)]
pub struct Section {
    pub n: [f64; 3],
    pub d: [f64; 3],
}

impl Section {
    pub fn at_s(&self, s: Complex64) -> Complex64 {
        (self.n[0] + s * self.n[1] + s * s * self.n[2])
            / (self.d[0] + s * self.d[1] + s * s * self.d[2])
    }
}
