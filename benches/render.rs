//! Frame costs of the TUI: the Responses tab drawn at 200×60 into a
//! TestBackend, and a parameter edit (key → update → redrawn frame).

use biodyn_app::tui;

use criterion::{Criterion, criterion_group, criterion_main};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::hint::black_box;
use tui::app::App;
use tui::event::Msg;
use tui::theme::Theme;
use tui::update::update;

/// Tab indices in the registry (`tui::tabs`): Model, Responses, Study.
const MODEL: usize = 0;
const RESPONSES: usize = 1;
const STUDY: usize = 2;

fn app(tab: usize) -> App {
    let mut a = App::new(biodyn::Preset::builtin_default(), None, Theme::default());
    a.current = tab;
    a
}

fn key(c: char) -> Msg {
    Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
}

fn bench(c: &mut Criterion) {
    let a = app(RESPONSES);
    let mut term = Terminal::new(TestBackend::new(200, 60)).expect("backend");
    c.bench_function("draw responses 200x60", |b| {
        b.iter(|| {
            term.draw(|f| tui::draw(f, black_box(&a))).expect("draw");
        })
    });
    // A frame that differs from the last one: the cursor moves each time,
    // so the backend receives the changed cells too.
    let mut a2 = app(RESPONSES);
    let mut term2 = Terminal::new(TestBackend::new(200, 60)).expect("backend");
    let mut right = true;
    c.bench_function("cursor key then draw responses 200x60", |b| {
        b.iter(|| {
            let code = if right { KeyCode::Right } else { KeyCode::Left };
            right = !right;
            update(&mut a2, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
            term2.draw(|f| tui::draw(f, &a2)).expect("draw");
        })
    });
    for (name, tab) in [
        ("edit k (+5%) then draw model 200x60", MODEL),
        ("edit k (+5%) then draw responses 200x60", RESPONSES),
        ("edit k (+5%) then draw study 200x60", STUDY),
    ] {
        let mut a = app(MODEL);
        // select k4: body mass, 4 segments, then links k1..k4
        for _ in 0..8 {
            update(
                &mut a,
                Msg::Key(KeyEvent::new(KeyCode::Down, KeyModifiers::NONE)),
            );
        }
        let mut term = Terminal::new(TestBackend::new(200, 60)).expect("backend");
        let mut up = true;
        c.bench_function(name, |b| {
            b.iter(|| {
                a.current = MODEL;
                update(&mut a, key(if up { '+' } else { '-' }));
                up = !up;
                a.current = tab;
                term.draw(|f| tui::draw(f, &a)).expect("draw");
            })
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
