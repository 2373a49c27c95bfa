//! The Study tab's export (`x`): the study as the command line writes it.

use super::StudyTab;
use crate::tui::effect::{Effect, Export, Format};
use crate::tui::shared::Shared;
use crate::view::report::plot::{PLOT_HEIGHT, PLOT_WIDTH, PlotText};
use crate::view::report::study as report;
use biodyn::{Function, Param};

impl StudyTab {
    /// The shown study as CSV (`biodyn study … --format csv`) or, for a
    /// name ending in .txt (.svg: as `--format svg`), the current function's chart as text (`biodyn
    /// plot <f> --study … --width 100 --height 30`, with `--log-x --log-y`
    /// when the axes are log).
    pub(super) fn export(&self, s: &Shared) -> Vec<Effect> {
        let Some(Ok(study)) = &self.result else {
            return vec![Effect::Error(
                "no study to export yet (Enter edits the values)".into(),
            )];
        };
        let f = Function::ALL.get(self.func).copied().unwrap_or(Function::Stht);
        let p = self.param();
        let slug = match p {
            Param::BodyMass => "mass".to_string(),
            _ => s.body.label(p),
        };
        let chart = report::chart_text(
            study,
            PlotText {
                function: f,
                log_x: self.log,
                log_y: self.log,
                ascii: s.theme.ascii,
                width: PLOT_WIDTH,
                height: PLOT_HEIGHT,
            },
        );
        vec![Effect::Export(Export {
            what: format!("study of {}", s.body.label(p)),
            path_hint: format!("{}-study-{slug}.csv", s.preset.name),
            formats: vec![
                Format {
                    ext: "csv",
                    what: "curves",
                    contents: report::curves_csv(study),
                },
                Format {
                    ext: "txt",
                    what: "text chart",
                    contents: chart,
                },
                Format {
                    ext: "svg",
                    what: "figure",
                    contents: report::figure_svg(study, f, self.log),
                },
            ],
        })]
    }

}
