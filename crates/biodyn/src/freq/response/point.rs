//! The three functions at one frequency: what every solver path returns
//! (`Solver`, the chain kernel in `freq::chain`).

use crate::freq::function::Function;
use num_complex::Complex64;

/// The three functions at one frequency, as complex ratios to the seat motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Response {
    pub f_hz: f64,
    /// X_head / X0, dimensionless.
    pub stht: Complex64,
    /// F / (jω X0), N·s/m.
    pub dpmi: Complex64,
    /// F / (−ω² X0), kg.
    pub apms: Complex64,
}

impl Response {
    pub fn get(&self, f: Function) -> Complex64 {
        match f {
            Function::Stht => self.stht,
            Function::Dpmi => self.dpmi,
            Function::Apms => self.apms,
        }
    }

    pub fn mag(&self, f: Function) -> f64 {
        self.get(f).norm()
    }

    pub fn phase_deg(&self, f: Function) -> f64 {
        phase_deg(self.get(f))
    }
}

/// Phase in degrees in (−180, 180].
pub fn phase_deg(z: Complex64) -> f64 {
    let d = z.im.atan2(z.re).to_degrees();
    if d <= -180.0 { d + 360.0 } else { d }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phase_is_in_half_open_interval() {
        assert_eq!(phase_deg(Complex64::new(-1.0, -0.0)), 180.0);
        assert_eq!(phase_deg(Complex64::new(-1.0, 0.0)), 180.0);
        assert!((phase_deg(Complex64::new(0.0, 1.0)) - 90.0).abs() < 1e-12);
    }
}
