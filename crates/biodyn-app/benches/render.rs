//! Frame costs of the TUI: the Responses tab drawn at 200×60 into a
//! TestBackend, and a parameter edit (key → update → redrawn frame).

use biodyn_app::tui;

use criterion::{Criterion, criterion_group, criterion_main};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::hint::black_box;
use tui::app::{App, Tab, update};
use tui::event::Msg;
use tui::theme::Theme;

fn app(tab: Tab) -> App {
    let mut a = App::new(biodyn::Preset::builtin_default(), None, Theme::default());
    a.tab = tab;
    a
}

fn key(c: char) -> Msg {
    Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
}

fn bench(c: &mut Criterion) {
    let a = app(Tab::Responses);
    let mut term = Terminal::new(TestBackend::new(200, 60)).expect("backend");
    c.bench_function("draw responses 200x60", |b| {
        b.iter(|| {
            term.draw(|f| tui::draw(f, black_box(&a))).expect("draw");
        })
    });
    // A frame that differs from the last one: the cursor moves each time,
    // so the backend receives the changed cells too.
    let mut a2 = app(Tab::Responses);
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
        ("edit k (+5%) then draw model 200x60", Tab::Model),
        ("edit k (+5%) then draw responses 200x60", Tab::Responses),
        ("edit k (+5%) then draw study 200x60", Tab::Study),
    ] {
        let mut a = app(Tab::Model);
        // select k4: body mass, 4 segments, then links k1..k4
        a.model.row = 8;
        let mut term = Terminal::new(TestBackend::new(200, 60)).expect("backend");
        let mut up = true;
        c.bench_function(name, |b| {
            b.iter(|| {
                a.tab = Tab::Model;
                update(&mut a, key(if up { '+' } else { '-' }));
                up = !up;
                a.tab = tab;
                term.draw(|f| tui::draw(f, &a)).expect("draw");
            })
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
