//! Trend sentences of a study, for both fronts (`biodyn study`'s table and
//! the Study tab).

use crate::view::format::num;
use biodyn::freq::{Direction, Study, Trend};

/// Two or more different values: something to compare.
pub fn comparable(study: &Study) -> bool {
    study
        .variants
        .iter()
        .any(|v| study.variants.first().is_some_and(|f| f.value != v.value))
}

/// Why a study has no trends ("one value: nothing to compare"), in place
/// of sentences that would say every peak "stays put" over 0 % of the
/// band; None when there is something to compare. Each front adds how to
/// give more values.
pub fn nothing_to_compare(study: &Study) -> Option<&'static str> {
    if comparable(study) {
        return None;
    }
    Some(if study.variants.len() == 1 {
        "one value: nothing to compare"
    } else {
        "the values are all the same: nothing to compare"
    })
}

/// "As k4 rises, the STHT peak rises and moves up in frequency; the curve
/// rises over 62% of the band and falls over 30%."
pub fn sentence(param: &str, t: &Trend) -> String {
    let mag = match t.peak_mag {
        Direction::Rises => "rises",
        Direction::Falls => "falls",
        Direction::Mixed => "goes up and down",
        Direction::Flat => "stays put",
    };
    let f = match t.peak_f {
        Direction::Rises => "moves up in frequency",
        Direction::Falls => "moves down in frequency",
        Direction::Mixed => "moves back and forth in frequency",
        Direction::Flat => "stays at the same frequency",
    };
    format!(
        "As {param} rises, the {} peak {mag} and {f}; the curve rises over {}% of the band and falls over {}%.",
        t.function.name(),
        num(t.rises_share * 100.0, 2),
        num(t.falls_share * 100.0, 2)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use biodyn::Function;

    #[test]
    fn a_sentence_names_the_parameter_the_directions_and_the_shares() {
        let t = Trend {
            function: Function::ALL[0],
            peak_mag: Direction::Falls,
            peak_f: Direction::Mixed,
            rises_share: 0.234,
            falls_share: 0.76,
        };
        assert_eq!(
            sentence("body mass", &t),
            format!(
                "As body mass rises, the {} peak falls and moves back and forth in frequency; \
                 the curve rises over 23% of the band and falls over 76%.",
                Function::ALL[0].name()
            )
        );
    }
}
