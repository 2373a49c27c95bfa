//! The tabs, each one component (`component::Tab`) in its own file. The
//! registry at the bottom is the only place that lists them: one line per
//! tab declares its module and puts it in the tab bar. Their order is the
//! tab bar's, and tab `i` opens with the digit `i + 1`.

use super::component::Tab;
use super::shared::Shared;

/// `module::Type,` per tab: declares `mod module;` and builds the tab
/// with `Type::new(shared)`, in this order.
macro_rules! register {
    ($($module:ident :: $ty:ident),+ $(,)?) => {
        $(pub mod $module;)+

        /// Every tab, in tab-bar order, built for the loaded model.
        pub fn all(shared: &Shared) -> Vec<Box<dyn Tab>> {
            vec![$(Box::new($module::$ty::new(shared))),+]
        }
    };
}

register! {
    model::ModelTab,
    responses::ResponsesTab,
    study::StudyTab,
    training::TrainingTab,
    vibration::VibrationTab,
    day::DayTab,
    seat::SeatTab,
}
