//! The page's one stylesheet, inline: on screen the page is an A4 sheet's
//! text width (178 mm: 210 mm less 16 mm margins each side), so what the
//! reader sees is what the printer gets. The print rules only take the
//! screen's frame away and keep things whole: `@page` A4 with margins, a
//! table row, a verdict or a figure never split across pages, headings kept
//! with what follows, tables' heads repeated, backgrounds printed (the
//! verdicts' tints; their words carry the meaning without them); the short
//! sections (verdicts, comfort, the spine) kept on one page with their
//! headings. Fonts by
//! generic family only: nothing to download.

pub const CSS: &str = r#":root { --ink: #1b1f23; --muted: #57606a; --rule: #d0d7de; --band: #f3f5f7; }
* { box-sizing: border-box; }
html { background: #e9ecef; }
body { margin: 0; color: var(--ink); font: 10pt/1.4 system-ui, -apple-system, "Segoe UI", sans-serif; }
main { width: 178mm; max-width: 100%; margin: 8mm auto; padding: 12mm 0; background: #fff; }
main > * { margin-left: 10mm; margin-right: 10mm; }
@media screen { main { width: 198mm; box-shadow: 0 1px 4px rgba(0,0,0,.25); } }
header { border-bottom: 2px solid var(--ink); padding-bottom: 3mm; margin-bottom: 4mm; }
h1 { font-size: 17pt; margin: 0 0 1mm; }
h2 { font-size: 12pt; margin: 6mm 0 2mm; border-bottom: 1px solid var(--rule); padding-bottom: 1mm; break-after: avoid; }
h3 { font-size: 10.5pt; margin: 4mm 0 1.5mm; break-after: avoid; }
p { margin: 1.5mm 0; }
.sub { color: var(--muted); margin: 0; overflow-wrap: anywhere; }
.note { color: var(--muted); font-size: 8.5pt; }
code { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 9pt; overflow-wrap: anywhere; }
table { border-collapse: collapse; width: 100%; margin: 1.5mm 0 2mm; font-size: 9pt; font-variant-numeric: tabular-nums; }
th, td { padding: 0.8mm 1.6mm; border-bottom: 1px solid var(--rule); text-align: left; vertical-align: top; }
th { background: var(--band); font-weight: 600; }
td.num, th.num { text-align: right; }
td.num { white-space: nowrap; }
table.axes td:first-child, table.daily td:first-child, table.week td:first-child { white-space: nowrap; }
tr.top td { font-weight: 600; }
table.facts th { width: 32%; background: none; font-weight: 600; }
table.facts td { overflow-wrap: anywhere; }
table.facts td.num { text-align: left; }
.verdicts { display: grid; grid-template-columns: 1fr 1fr; gap: 3mm; margin: 2mm 0; }
.verdict { border: 1px solid var(--rule); border-left: 3mm solid; padding: 2mm 3mm; break-inside: avoid; }
.verdict .what { font-size: 8.5pt; color: var(--muted); }
.verdict .value { font-size: 12pt; font-weight: 600; }
.verdict .words { font-size: 11pt; font-weight: 700; text-transform: uppercase; letter-spacing: .02em; }
.verdict p { font-size: 8.5pt; }
.verdict.below { border-left-color: #2da44e; background: #eef8f0; }
.verdict.action { border-left-color: #bf8700; background: #fff8e1; }
.verdict.limit { border-left-color: #cf222e; background: #ffebe9; }
.verdict.none { border-left-color: var(--muted); }
.model { border: 1px dashed var(--muted); padding: 1.5mm 3mm; margin: 2mm 0; background: #f6f8fa; }
.model-tag { font-weight: 600; font-style: italic; }
ul { margin: 1mm 0; padding-left: 6mm; }
li { margin: 0.5mm 0; }
figure { margin: 3mm 0; break-inside: avoid; }
figure svg { width: 100%; height: auto; }
footer { margin-top: 8mm; border-top: 2px solid var(--ink); font-size: 8.5pt; color: var(--muted); }
footer h2 { border: none; color: var(--ink); }
@page { size: A4; margin: 16mm 16mm 18mm; }
@media print {
  html, body { background: #fff; }
  main { width: auto; margin: 0; padding: 0; box-shadow: none; }
  main > * { margin-left: 0; margin-right: 0; }
  * { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
  tr, .verdict, figure, .keep { break-inside: avoid; }
  #meta, #verdicts, #comfort, #spine, #seat, #week, #warnings { break-inside: avoid; }
  thead { display: table-header-group; }
  h2, h3 { break-after: avoid; }
}
"#;
