//! The response functions, one table entry each ([`SPECS`]): name, unit,
//! CSV columns and JSON keys, the decimals the tables print, and where the
//! value sits in a [`Response`]. Every loop over functions runs over
//! [`Function::ALL`], and every front reads a function's metadata from its
//! entry. A new function is a variant, its entry, and a field of
//! `Response` that the compiler then asks every solver path to fill.

use num_complex::Complex64;
use serde::Serialize;

/// The three response functions of the paper, then the two a seat adds.
/// With a seat (SPEC §11) the paper's three are taken at the pan, as a lab
/// measures them on a seat: STHT pan to head, APMS and DPMI the pan's force
/// on the body over the pan's motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Function {
    Stht,
    Dpmi,
    Apms,
    /// The seat's transmissibility: pan motion over floor motion.
    SeatTr,
    /// Floor to head: the head's motion over the floor's.
    FloorHead,
}

/// Which solved quantity a function is, up to a factor that depends on ω
/// alone (the fit differentiates that quantity and so has the derivative
/// of the function's logarithm).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// The head's motion, H_head.
    Head,
    /// The seat force, Σ m_i H_i.
    SeatForce,
    /// The seat pan's motion (a seat model's own functions: not fitted).
    Pan,
}

/// Everything about one response function.
#[derive(Debug, Clone, Copy)]
pub struct Spec {
    pub function: Function,
    /// Lower-case key as used on the command line and in CSV headers.
    pub key: &'static str,
    pub name: &'static str,
    pub long_name: &'static str,
    /// Unit of the magnitude ("-" when dimensionless).
    pub unit: &'static str,
    /// CSV column and JSON key of the magnitude: `stht_mag`.
    pub mag_column: &'static str,
    /// CSV column and JSON key of the phase: `stht_phase_deg`.
    pub phase_column: &'static str,
    /// Decimals of a magnitude in a response table: what the paper's
    /// figures resolve.
    pub mag_decimals: usize,
    /// Decimals of a peak magnitude in the study table.
    pub peak_decimals: usize,
    /// The value at one frequency.
    pub get: fn(&Response) -> Complex64,
    /// What the fit's adjoint differentiates for it.
    pub source: Source,
}

/// One entry per function, in the order of [`Function::EVERY`]: the body's
/// three ([`Function::ALL`]) first, then a seat's ([`Function::SEAT`]).
pub const SPECS: [Spec; 5] = [
    Spec {
        function: Function::Stht,
        key: "stht",
        name: "STHT",
        long_name: "seat-to-head transmissibility",
        unit: "-",
        mag_column: "stht_mag",
        phase_column: "stht_phase_deg",
        mag_decimals: 4,
        peak_decimals: 4,
        get: |r| r.stht,
        source: Source::Head,
    },
    Spec {
        function: Function::Dpmi,
        key: "dpmi",
        name: "DPMI",
        long_name: "driving-point mechanical impedance",
        unit: "N·s/m",
        mag_column: "dpmi_mag",
        phase_column: "dpmi_phase_deg",
        mag_decimals: 1,
        peak_decimals: 2,
        get: |r| r.dpmi,
        source: Source::SeatForce,
    },
    Spec {
        function: Function::Apms,
        key: "apms",
        name: "APMS",
        long_name: "apparent mass",
        unit: "kg",
        mag_column: "apms_mag",
        phase_column: "apms_phase_deg",
        mag_decimals: 2,
        peak_decimals: 2,
        get: |r| r.apms,
        source: Source::SeatForce,
    },
    Spec {
        function: Function::SeatTr,
        key: "seat_tr",
        name: "SEAT T",
        long_name: "seat transmissibility (pan over floor)",
        unit: "-",
        mag_column: "seat_tr_mag",
        phase_column: "seat_tr_phase_deg",
        mag_decimals: 4,
        peak_decimals: 4,
        get: |r| r.seat_tr,
        source: Source::Pan,
    },
    Spec {
        function: Function::FloorHead,
        key: "floor_head",
        name: "floor-head",
        long_name: "floor-to-head transmissibility",
        unit: "-",
        mag_column: "floor_head_mag",
        phase_column: "floor_head_phase_deg",
        mag_decimals: 4,
        peak_decimals: 4,
        get: |r| r.floor_head,
        source: Source::Pan,
    },
];

/// How many of [`SPECS`] are the body's functions (the rest are a seat's).
const BODY_FUNCTIONS: usize = 3;

impl Function {
    /// Every function, in table order.
    pub const EVERY: [Function; SPECS.len()] = {
        let mut out = [Function::Stht; SPECS.len()];
        let mut i = 0;
        while i < out.len() {
            out[i] = SPECS[i].function;
            // The entry of a function sits at its index (`spec` relies on it).
            assert!(SPECS[i].function as usize == i);
            i += 1;
        }
        out
    };

    /// The body's functions (the paper's three): what every model has, and
    /// what studies, fits and the networks run over.
    pub const ALL: [Function; BODY_FUNCTIONS] = {
        let mut out = [Function::Stht; BODY_FUNCTIONS];
        let mut i = 0;
        while i < BODY_FUNCTIONS {
            out[i] = Function::EVERY[i];
            i += 1;
        }
        out
    };

    /// The functions a seat adds: its transmissibility and floor to head.
    pub const SEAT: [Function; SPECS.len() - BODY_FUNCTIONS] = {
        let mut out = [Function::SeatTr; SPECS.len() - BODY_FUNCTIONS];
        let mut i = 0;
        while i < out.len() {
            out[i] = Function::EVERY[BODY_FUNCTIONS + i];
            i += 1;
        }
        out
    };

    /// The functions a model has: the body's three, and a seat's two when
    /// it has a seat.
    pub fn of(has_seat: bool) -> &'static [Function] {
        if has_seat {
            &Function::EVERY
        } else {
            &Function::ALL
        }
    }

    /// True for the functions only a seat model has.
    pub fn needs_seat(self) -> bool {
        self.index() >= BODY_FUNCTIONS
    }

    /// The function's table entry.
    pub const fn spec(self) -> &'static Spec {
        &SPECS[self as usize]
    }

    /// Lower-case key as used on the command line and in CSV headers.
    pub fn key(self) -> &'static str {
        self.spec().key
    }

    pub fn name(self) -> &'static str {
        self.spec().name
    }

    pub fn long_name(self) -> &'static str {
        self.spec().long_name
    }

    /// Unit of the magnitude.
    pub fn unit(self) -> &'static str {
        self.spec().unit
    }

    /// Position in `EVERY` (and in `ALL` for the body's three: per-function
    /// arrays over `ALL` are indexed by it).
    pub fn index(self) -> usize {
        self as usize
    }

    /// CSV column and JSON key of the magnitude: `stht_mag`.
    pub const fn mag_column(self) -> &'static str {
        self.spec().mag_column
    }

    /// CSV column and JSON key of the phase: `stht_phase_deg`.
    pub const fn phase_column(self) -> &'static str {
        self.spec().phase_column
    }

    /// Decimals of a magnitude in a response table.
    pub fn mag_decimals(self) -> usize {
        self.spec().mag_decimals
    }

    /// Decimals of a peak magnitude in the study table.
    pub fn peak_decimals(self) -> usize {
        self.spec().peak_decimals
    }

    /// What the fit's adjoint differentiates for this function.
    pub fn source(self) -> Source {
        self.spec().source
    }

    /// The unit for a label, empty for the dimensionless STHT.
    pub fn unit_label(self) -> &'static str {
        match self.unit() {
            "-" => "",
            u => u,
        }
    }

    /// The function named by its key, any case (a seat's functions too).
    pub fn parse(s: &str) -> Option<Function> {
        let s = s.trim();
        Function::EVERY
            .into_iter()
            .find(|f| f.key().eq_ignore_ascii_case(s))
    }
}

/// The functions at one frequency, as complex ratios to the seat motion:
/// what every solver path returns (`Solver`, the chain kernel in
/// `freq::chain`, the fit's model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Response {
    pub f_hz: f64,
    /// X_head / X0, dimensionless.
    pub stht: Complex64,
    /// F / (jω X0), N·s/m.
    pub dpmi: Complex64,
    /// F / (−ω² X0), kg.
    pub apms: Complex64,
    /// X_pan / X_floor; 1 on a rigid seat (the pan is the floor).
    pub seat_tr: Complex64,
    /// X_head / X_floor; STHT on a rigid seat.
    pub floor_head: Complex64,
}

impl Response {
    /// The functions from the head's motion H_head and the apparent mass
    /// Σ m_i H_i at ω = 2π f_hz: every solver path builds its result here.
    #[inline]
    pub fn of(f_hz: f64, w: f64, stht: Complex64, apms: Complex64) -> Response {
        Response {
            f_hz,
            stht,
            apms,
            dpmi: Complex64::new(0.0, w) * apms,
            seat_tr: Complex64::new(1.0, 0.0),
            floor_head: stht,
        }
    }

    /// The functions of a seat model from the floor-referenced motions: the
    /// head's H_head, the pan's H_pan and the body's Σ m_i H_i (body
    /// segments only), each per unit floor motion. Referred to the pan:
    /// STHT = H_head/H_pan, APMS = Σ m_i H_i / H_pan (Newton on the body:
    /// the pan's force is −ω² Σ m_i X_i), DPMI = jω·APMS.
    #[inline]
    pub fn on_seat(
        f_hz: f64,
        w: f64,
        head: Complex64,
        pan: Complex64,
        body: Complex64,
    ) -> Response {
        let stht = head / pan;
        let apms = body / pan;
        Response {
            f_hz,
            stht,
            apms,
            dpmi: Complex64::new(0.0, w) * apms,
            seat_tr: pan,
            floor_head: head,
        }
    }

    pub fn get(&self, f: Function) -> Complex64 {
        (f.spec().get)(self)
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
    fn index_columns_and_keys_follow_all() {
        assert_eq!(
            Function::ALL,
            [Function::Stht, Function::Dpmi, Function::Apms]
        );
        assert_eq!(Function::SEAT, [Function::SeatTr, Function::FloorHead]);
        assert!(Function::SEAT.iter().all(|f| f.needs_seat()));
        assert!(!Function::ALL.iter().any(|f| f.needs_seat()));
        for (i, f) in Function::EVERY.into_iter().enumerate() {
            assert_eq!(f.index(), i);
            assert_eq!(f.spec().function, f);
            assert_eq!(f.mag_column(), format!("{}_mag", f.key()));
            assert_eq!(f.phase_column(), format!("{}_phase_deg", f.key()));
            assert_eq!(Function::parse(f.key()), Some(f));
            assert_eq!(Function::parse(&f.key().to_uppercase()), Some(f));
        }
    }

    #[test]
    fn each_entry_reads_its_own_field() {
        let c = |x: f64| Complex64::new(x, -x);
        let r = Response {
            f_hz: 1.0,
            stht: c(1.0),
            dpmi: c(2.0),
            apms: c(3.0),
            seat_tr: c(4.0),
            floor_head: c(5.0),
        };
        assert_eq!(r.get(Function::Stht), r.stht);
        assert_eq!(r.get(Function::Dpmi), r.dpmi);
        assert_eq!(r.get(Function::Apms), r.apms);
        assert_eq!(r.get(Function::SeatTr), r.seat_tr);
        assert_eq!(r.get(Function::FloorHead), r.floor_head);
    }

    #[test]
    fn phase_is_in_half_open_interval() {
        assert_eq!(phase_deg(Complex64::new(-1.0, -0.0)), 180.0);
        assert_eq!(phase_deg(Complex64::new(-1.0, 0.0)), 180.0);
        assert!((phase_deg(Complex64::new(0.0, 1.0)) - 90.0).abs() < 1e-12);
    }
}
