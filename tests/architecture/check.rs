//! The architecture checker: reads a source tree (paths and texts, so a test
//! can hand it a tiny tree in memory), builds the module graph of each crate
//! and returns every broken rule as one line.
//!
//! What counts as an edge `A → B`: a `use` of B, or a path into B in code or
//! in a macro's tokens (`crate::x::y`, `super::y`, `self::y`, a child's
//! `y::f`, or a name a `use` brought in), where B is the deepest module the
//! path names; a path through a re-export (`crate::Band`, `pub use
//! freq::band::Band`) is followed to where the item lives. A module's use
//! of an ancestor is an edge only when the ancestor's own file defines the
//! item (`super::Shared` with `pub struct Shared` in `mod.rs`), or the
//! module globs it (`use super::*`) and that file defines any item: a name the
//! ancestor re-exports leads to the module defining it, and one that names
//! a module is the module tree, not a use. So a parent whose children use
//! its own items while it uses them is a circle, and a `mod.rs` of `mod`
//! and `pub use` lines over children that use each other is not. The
//! crate's [`Crate::components`] are the exceptions the tree keeps. Code
//! under `#[cfg(test)]` and `#[test]`, comments and doc comments are not
//! read.

use proc_macro2::{TokenStream, TokenTree};
use std::collections::{BTreeMap, BTreeSet, VecDeque};
use syn::visit::Visit;

/// Longest non-test source file, in lines.
pub const MAX_LINES: usize = 500;

/// Files allowed past [`MAX_LINES`] because they are pure tables (data, no
/// logic), by path, each with why. None today: the key tables share
/// `src/tui/keys.rs` with the code that matches keys, so it is not one.
pub const PURE_TABLES: &[(&str, &str)] = &[];

/// One crate to check: its name in the graph, its root file, and whether it
/// is the library (no terminal code, no printing, no flags in its strings).
pub struct Crate {
    pub name: &'static str,
    pub root: &'static str,
    pub library: bool,
    /// Items (path from the crate root, `tui::app::App`) that the children
    /// of the module defining them may use while it uses those children: a
    /// component's type in its `mod.rs`, its impl, view and keys spread over
    /// the children. Each with why.
    pub components: &'static [(&'static str, &'static str)],
}

/// A module found from a crate's root.
struct Module {
    krate: &'static str,
    library: bool,
    /// From the crate root: `["cli", "man"]`; the root is `[]`.
    path: Vec<String>,
    /// The file it is in (an inline module's is its parent's).
    file: String,
    children: BTreeSet<String>,
    /// Names brought in by `use`: name → path as written, line.
    uses: Vec<(String, Vec<String>, usize)>,
    /// Paths in code and macro tokens, with their line.
    refs: Vec<(Vec<String>, usize)>,
    /// Names of the items its own code defines (not `mod`, not `use`).
    defines: BTreeSet<String>,
    prints: Vec<(String, usize)>,
    strings: Vec<(String, usize)>,
}

impl Module {
    fn name(&self) -> String {
        if self.path.is_empty() {
            format!("{}::", self.krate)
        } else {
            format!("{}::{}", self.krate, self.path.join("::"))
        }
    }
}

/// The rules broken in `files` (path from the repository root → text), one
/// line each; empty when the tree keeps them all.
pub fn check(files: &BTreeMap<String, String>, crates: &[Crate]) -> Vec<String> {
    let mut problems = Vec::new();
    let mut modules = Vec::new();
    let mut module_files = BTreeSet::new();
    for c in crates {
        let Some(text) = files.get(c.root) else {
            problems.push(format!("{}: the crate root is missing", c.root));
            continue;
        };
        match syn::parse_file(text) {
            Ok(f) => {
                let dir = child_dir(c.root);
                walk(
                    c,
                    Vec::new(),
                    c.root,
                    &dir,
                    &f.items,
                    files,
                    &mut modules,
                    &mut module_files,
                    &mut problems,
                );
            }
            Err(e) => problems.push(format!("{}: does not parse: {e}", c.root)),
        }
    }
    let index: BTreeMap<(String, Vec<String>), usize> = modules
        .iter()
        .enumerate()
        .map(|(i, m)| ((m.krate.to_string(), m.path.clone()), i))
        .collect();
    let graph = Graph {
        modules: &modules,
        crates,
        used: Default::default(),
        index: &index,
    };
    let edges = graph.edges();
    // An exception nothing needs any more is dropped from the list.
    for c in crates {
        for (path, _) in c.components {
            if !graph
                .used
                .borrow()
                .contains(&(c.name.to_string(), path.to_string()))
            {
                problems.push(format!(
                    "{}::{path} is listed as a component's item, but no child of its module uses it: drop it from the list",
                    c.name
                ));
            }
        }
    }
    problems.extend(cycles(&modules, &edges));
    problems.extend(fronts_and_tabs(&modules, &edges));
    problems.extend(library_rules(&modules, files, crates));
    problems.extend(long_files(files, &module_files));
    problems
}

/// Where the children of the module in `file` live: beside a `mod.rs`,
/// `lib.rs` or `main.rs`, in a folder named after any other file.
fn child_dir(file: &str) -> String {
    let (dir, name) = file.rsplit_once('/').unwrap_or(("", file));
    match name {
        "mod.rs" | "lib.rs" | "main.rs" => dir.to_string(),
        _ => format!("{dir}/{}", name.trim_end_matches(".rs")),
    }
}

fn dir_of(file: &str) -> &str {
    file.rsplit_once('/').map_or("", |(d, _)| d)
}

/// Whether an item is test code: `#[test]`, or a `cfg` that needs `test`.
fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        if a.path().is_ident("test") {
            return true;
        }
        if !a.path().is_ident("cfg") {
            return false;
        }
        let syn::Meta::List(l) = &a.meta else {
            return false;
        };
        let text = l.tokens.to_string();
        let words: Vec<&str> = text
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .collect();
        words.contains(&"test") && !words.contains(&"not")
    })
}

fn path_attr(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find_map(|a| match &a.meta {
        syn::Meta::NameValue(nv) if nv.path.is_ident("path") => match &nv.value {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) => Some(s.value()),
            _ => None,
        },
        _ => None,
    })
}

/// Records the module at `path` and walks into its non-test children.
#[allow(clippy::too_many_arguments)]
fn walk(
    c: &Crate,
    path: Vec<String>,
    file: &str,
    dir: &str,
    items: &[syn::Item],
    files: &BTreeMap<String, String>,
    modules: &mut Vec<Module>,
    module_files: &mut BTreeSet<String>,
    problems: &mut Vec<String>,
) {
    module_files.insert(file.to_string());
    let mut collect = Collect::default();
    let mut children = BTreeSet::new();
    let mut nested = Vec::new();
    let mut macro_mods = Vec::new();
    for item in items {
        if let syn::Item::Mod(m) = item {
            if is_test(&m.attrs) {
                continue;
            }
            let name = m.ident.to_string();
            children.insert(name.clone());
            nested.push(m);
            continue;
        }
        if let syn::Item::Macro(m) = item
            && !m.mac.path.is_ident("macro_rules")
            && !is_test(&m.attrs)
        {
            // A registry macro that declares modules (`register! {
            // model::ModelTab, … }` expands to `pub mod model;`): a name in
            // its tokens with a module file where `mod name;` would look.
            let mut names = Vec::new();
            idents(m.mac.tokens.clone(), &mut names);
            for name in names {
                let has_file = [format!("{dir}/{name}.rs"), format!("{dir}/{name}/mod.rs")]
                    .iter()
                    .any(|p| files.contains_key(p));
                if has_file && children.insert(name.clone()) {
                    macro_mods.push(name);
                }
            }
        }
        collect.visit_item(item);
    }
    modules.push(Module {
        krate: c.name,
        library: c.library,
        path: path.clone(),
        file: file.to_string(),
        children,
        uses: collect.uses,
        refs: collect.refs,
        defines: items
            .iter()
            .filter(|i| !is_test(item_attrs(i)))
            .filter_map(defined_name)
            .collect(),
        prints: collect.prints,
        strings: collect.strings,
    });
    let declared = nested
        .iter()
        .map(|m| (m.ident.to_string(), m.content.as_ref(), path_attr(&m.attrs)))
        .chain(macro_mods.into_iter().map(|n| (n, None, None)));
    for (name, content, path_attr) in declared {
        let mut sub = path.clone();
        sub.push(name.clone());
        if let Some((_, content)) = content {
            walk(
                c,
                sub,
                file,
                &format!("{dir}/{name}"),
                content,
                files,
                modules,
                module_files,
                problems,
            );
            continue;
        }
        let candidates = match path_attr {
            Some(p) => vec![format!("{}/{p}", dir_of(file))],
            None => vec![format!("{dir}/{name}.rs"), format!("{dir}/{name}/mod.rs")],
        };
        let Some(found) = candidates.iter().find(|p| files.contains_key(*p)) else {
            problems.push(format!(
                "{file}: `mod {name};` has no file ({})",
                candidates.join(" or ")
            ));
            continue;
        };
        match syn::parse_file(&files[found]) {
            Ok(f) => walk(
                c,
                sub,
                found,
                &child_dir(found),
                &f.items,
                files,
                modules,
                module_files,
                problems,
            ),
            Err(e) => problems.push(format!("{found}: does not parse: {e}")),
        }
    }
}

/// What one module's non-test items say: its `use`s, paths, prints and
/// string literals.
#[derive(Default)]
struct Collect {
    uses: Vec<(String, Vec<String>, usize)>,
    refs: Vec<(Vec<String>, usize)>,
    prints: Vec<(String, usize)>,
    strings: Vec<(String, usize)>,
}

const PRINTS: [&str; 5] = ["println", "eprintln", "print", "eprint", "dbg"];

fn item_attrs(item: &syn::Item) -> &[syn::Attribute] {
    use syn::Item::*;
    match item {
        Const(i) => &i.attrs,
        Enum(i) => &i.attrs,
        ExternCrate(i) => &i.attrs,
        Fn(i) => &i.attrs,
        ForeignMod(i) => &i.attrs,
        Impl(i) => &i.attrs,
        Macro(i) => &i.attrs,
        Mod(i) => &i.attrs,
        Static(i) => &i.attrs,
        Struct(i) => &i.attrs,
        Trait(i) => &i.attrs,
        TraitAlias(i) => &i.attrs,
        Type(i) => &i.attrs,
        Union(i) => &i.attrs,
        Use(i) => &i.attrs,
        _ => &[],
    }
}

/// The name an item defines, if it is one a path can name from outside
/// (`mod` and `use` lines define no item of the module's own).
fn defined_name(item: &syn::Item) -> Option<String> {
    use syn::Item::*;
    let ident = match item {
        Const(i) => &i.ident,
        Enum(i) => &i.ident,
        Fn(i) => &i.sig.ident,
        Static(i) => &i.ident,
        Struct(i) => &i.ident,
        Trait(i) => &i.ident,
        TraitAlias(i) => &i.ident,
        Type(i) => &i.ident,
        Union(i) => &i.ident,
        Macro(i) => i.ident.as_ref()?,
        _ => return None,
    };
    Some(ident.to_string())
}

fn line(span: proc_macro2::Span) -> usize {
    span.start().line
}

impl Collect {
    fn use_tree(&mut self, prefix: &mut Vec<String>, tree: &syn::UseTree, at: usize) {
        match tree {
            syn::UseTree::Path(p) => {
                prefix.push(p.ident.to_string());
                self.use_tree(prefix, &p.tree, line(p.ident.span()));
                prefix.pop();
            }
            syn::UseTree::Name(n) => {
                let name = n.ident.to_string();
                let mut full = prefix.clone();
                // `use super::x::{self}` names x itself.
                if name != "self" {
                    full.push(name.clone());
                }
                let alias = if name == "self" {
                    prefix.last().cloned().unwrap_or_default()
                } else {
                    name
                };
                self.uses.push((alias, full, line(n.ident.span())));
            }
            syn::UseTree::Rename(r) => {
                let mut full = prefix.clone();
                if r.ident != "self" {
                    full.push(r.ident.to_string());
                }
                self.uses
                    .push((r.rename.to_string(), full, line(r.ident.span())));
            }
            syn::UseTree::Glob(_) => self.uses.push(("*".into(), prefix.clone(), at)),
            syn::UseTree::Group(g) => {
                for t in &g.items {
                    self.use_tree(prefix, t, at);
                }
            }
        }
    }

    /// Paths, prints and string literals inside macro tokens, which syn
    /// leaves unparsed.
    fn tokens(&mut self, tokens: TokenStream) {
        let list: Vec<TokenTree> = tokens.into_iter().collect();
        let mut i = 0;
        while i < list.len() {
            match &list[i] {
                TokenTree::Group(g) => self.tokens(g.stream()),
                TokenTree::Literal(l) => {
                    if let syn::Lit::Str(s) = syn::Lit::new(l.clone()) {
                        self.strings.push((s.value(), line(l.span())));
                    }
                }
                TokenTree::Ident(id) => {
                    // Not the middle of a path already read.
                    let inside = i >= 2 && is_colon(&list[i - 1]) && is_colon(&list[i - 2]);
                    if !inside {
                        let mut segs = vec![id.to_string()];
                        let mut j = i;
                        while j + 3 < list.len() && is_colon(&list[j + 1]) && is_colon(&list[j + 2])
                        {
                            let TokenTree::Ident(next) = &list[j + 3] else {
                                break;
                            };
                            segs.push(next.to_string());
                            j += 3;
                        }
                        let name = id.to_string();
                        let bang = matches!(list.get(i + 1), Some(TokenTree::Punct(p)) if p.as_char() == '!');
                        if bang && PRINTS.contains(&name.as_str()) {
                            self.prints.push((name, line(id.span())));
                        }
                        if segs.len() > 1 {
                            self.refs.push((segs, line(id.span())));
                        }
                        i = j;
                    }
                }
                TokenTree::Punct(_) => {}
            }
            i += 1;
        }
    }

    fn attribute(&mut self, a: &syn::Attribute) {
        if a.path().is_ident("doc") {
            return;
        }
        match &a.meta {
            syn::Meta::List(l) => self.tokens(l.tokens.clone()),
            syn::Meta::NameValue(nv) => self.visit_expr(&nv.value),
            syn::Meta::Path(_) => {}
        }
    }
}

/// Every identifier in `tokens`, groups included.
fn idents(tokens: TokenStream, out: &mut Vec<String>) {
    for t in tokens {
        match t {
            TokenTree::Ident(i) => out.push(i.to_string()),
            TokenTree::Group(g) => idents(g.stream(), out),
            _ => {}
        }
    }
}

fn is_colon(t: &TokenTree) -> bool {
    matches!(t, TokenTree::Punct(p) if p.as_char() == ':')
}

impl<'ast> Visit<'ast> for Collect {
    fn visit_item(&mut self, i: &'ast syn::Item) {
        if is_test(item_attrs(i)) {
            return;
        }
        match i {
            // Inline modules are modules of their own (see `walk`).
            syn::Item::Mod(_) => {}
            syn::Item::Use(u) => {
                for a in &u.attrs {
                    self.attribute(a);
                }
                let at = line(u.use_token.span);
                self.use_tree(&mut Vec::new(), &u.tree, at);
            }
            _ => syn::visit::visit_item(self, i),
        }
    }

    fn visit_impl_item(&mut self, i: &'ast syn::ImplItem) {
        let attrs: &[syn::Attribute] = match i {
            syn::ImplItem::Const(c) => &c.attrs,
            syn::ImplItem::Fn(f) => &f.attrs,
            syn::ImplItem::Type(t) => &t.attrs,
            syn::ImplItem::Macro(m) => &m.attrs,
            _ => &[],
        };
        if !is_test(attrs) {
            syn::visit::visit_impl_item(self, i);
        }
    }

    fn visit_attribute(&mut self, a: &'ast syn::Attribute) {
        self.attribute(a);
    }

    fn visit_path(&mut self, p: &'ast syn::Path) {
        // One segment is a local name or an item a `use` brought in (that
        // `use` is an edge already); a path has two or more.
        if p.segments.len() > 1 {
            let segs = p.segments.iter().map(|s| s.ident.to_string()).collect();
            self.refs.push((segs, line(p.segments[0].ident.span())));
        }
        syn::visit::visit_path(self, p);
    }

    fn visit_macro(&mut self, m: &'ast syn::Macro) {
        self.visit_path(&m.path);
        if let Some(last) = m.path.segments.last() {
            let name = last.ident.to_string();
            if PRINTS.contains(&name.as_str()) {
                self.prints.push((name, line(last.ident.span())));
            }
        }
        // `macro_rules!` bodies and macro calls: read their tokens.
        self.tokens(m.tokens.clone());
    }

    fn visit_lit_str(&mut self, s: &'ast syn::LitStr) {
        self.strings.push((s.value(), line(s.span())));
    }
}

/// The module graph of every crate.
struct Graph<'a> {
    modules: &'a [Module],
    crates: &'a [Crate],
    /// The listed component items a child did use (crate, path).
    used: std::cell::RefCell<BTreeSet<(String, String)>>,
    index: &'a BTreeMap<(String, Vec<String>), usize>,
}

/// An edge's evidence: the file and line and the path as written.
type Edges = BTreeMap<(usize, usize), (String, usize, String)>;

impl Graph<'_> {
    /// Whether `item` of `m` is listed in its crate's [`Crate::components`].
    fn component(&self, m: &Module, item: &str) -> bool {
        let listed = self.listed(m, item);
        if listed {
            let mut path = m.path.clone();
            path.push(item.to_string());
            self.used
                .borrow_mut()
                .insert((m.krate.to_string(), path.join("::")));
        }
        listed
    }

    /// [`Graph::component`] without counting it as used.
    fn listed(&self, m: &Module, item: &str) -> bool {
        let mut path = m.path.clone();
        path.push(item.to_string());
        let path = path.join("::");
        self.crates
            .iter()
            .filter(|c| c.name == m.krate)
            .any(|c| c.components.iter().any(|(p, _)| *p == path))
    }

    fn find(&self, krate: &str, path: &[String]) -> Option<usize> {
        self.index.get(&(krate.to_string(), path.to_vec())).copied()
    }

    /// The module a path written in module `m` lands in, following `use`
    /// names and re-exports (a few steps at most), and the name the path
    /// goes on with there (an item of that module, or a name it imports).
    fn resolve(&self, m: usize, segs: &[String], depth: usize) -> Option<(usize, Option<String>)> {
        if depth > 8 || segs.is_empty() {
            return None;
        }
        let here = &self.modules[m];
        let krate = here.krate;
        let (mut cur, rest): (usize, &[String]) = match segs[0].as_str() {
            "crate" => (self.find(krate, &[])?, &segs[1..]),
            "self" => (m, &segs[1..]),
            "super" => {
                let ups = segs.iter().take_while(|s| *s == "super").count();
                let keep = here.path.len().checked_sub(ups)?;
                (self.find(krate, &here.path[..keep])?, &segs[ups..])
            }
            first if here.children.contains(first) => (m, segs),
            first => {
                // A name a `use` of this module brought in.
                let (_, full, _) = here.uses.iter().find(|(n, full, _)| {
                    n == first && full.first().is_some_and(|f| f != first || full.len() > 1)
                })?;
                let mut joined = full.clone();
                joined.extend_from_slice(&segs[1..]);
                return self.resolve(m, &joined, depth + 1);
            }
        };
        let mut i = 0;
        while i < rest.len() && self.modules[cur].children.contains(&rest[i]) {
            let mut p = self.modules[cur].path.clone();
            p.push(rest[i].clone());
            cur = self.find(krate, &p)?;
            i += 1;
        }
        // An item re-exported here (`pub use freq::band::Band`): follow it.
        if i < rest.len()
            && let Some((_, full, _)) = self.modules[cur]
                .uses
                .iter()
                .find(|(n, _, _)| *n == rest[i])
        {
            let mut joined = full.clone();
            joined.extend_from_slice(&rest[i + 1..]);
            if let Some(t) = self.resolve(cur, &joined, depth + 1) {
                return Some(t);
            }
        }
        Some((cur, rest.get(i).cloned()))
    }

    fn edges(&self) -> Edges {
        let mut edges = Edges::new();
        for (m, module) in self.modules.iter().enumerate() {
            let written = module
                .uses
                .iter()
                .map(|(n, p, l)| (p, *l, n == "*"))
                .chain(module.refs.iter().map(|(p, l)| (p, *l, false)));
            for (segs, line, glob) in written {
                let Some((t, item)) = self.resolve(m, segs, 0) else {
                    continue;
                };
                let target = &self.modules[t];
                // Itself, or an ancestor's re-export or module: not an edge;
                // an item the ancestor's own file defines is (module doc),
                // unless the ancestor is a component its crate lists. A
                // glob of the ancestor (`use super::*`) brings in every item
                // its file defines: an edge when one is not listed.
                let own = match &item {
                    Some(i) => target.defines.contains(i) && !self.component(target, i),
                    None => glob && target.defines.iter().any(|i| !self.listed(target, i)),
                };
                if t == m || (module.path.starts_with(&target.path) && !own) {
                    continue;
                }
                edges
                    .entry((m, t))
                    .or_insert_with(|| (module.file.clone(), line, segs.join("::")));
            }
        }
        edges
    }
}

/// Every circle of imports: one shortest cycle through each module of a
/// strongly connected set that no earlier cycle went through.
fn cycles(modules: &[Module], edges: &Edges) -> Vec<String> {
    let n = modules.len();
    let mut next = vec![Vec::new(); n];
    for &(a, b) in edges.keys() {
        next[a].push(b);
    }
    let mut out = Vec::new();
    for scc in strongly_connected(&next) {
        if scc.len() < 2 {
            continue;
        }
        let inside: BTreeSet<usize> = scc.iter().copied().collect();
        let mut covered = BTreeSet::new();
        for &start in &scc {
            if covered.contains(&start) {
                continue;
            }
            let Some(cycle) = shortest_cycle(start, &next, &inside) else {
                continue;
            };
            covered.extend(cycle.iter().copied());
            let hops: Vec<String> = cycle
                .windows(2)
                .map(|w| {
                    let (file, line, path) = &edges[&(w[0], w[1])];
                    format!("{} ({file}:{line} `{path}`)", modules[w[0]].name())
                })
                .collect();
            out.push(format!(
                "import circle: {} → back to {}",
                hops.join(" → "),
                modules[start].name()
            ));
        }
    }
    out
}

/// Tarjan's strongly connected components, each sorted, in a stable order.
fn strongly_connected(next: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct T<'a> {
        next: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        count: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(t: &mut T, v: usize) {
        t.index[v] = Some(t.count);
        t.low[v] = t.count;
        t.count += 1;
        t.stack.push(v);
        t.on[v] = true;
        for &w in &t.next[v] {
            match t.index[w] {
                None => {
                    visit(t, w);
                    t.low[v] = t.low[v].min(t.low[w]);
                }
                Some(i) if t.on[w] => t.low[v] = t.low[v].min(i),
                _ => {}
            }
        }
        if Some(t.low[v]) == t.index[v] {
            let mut scc = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on[w] = false;
                scc.push(w);
                if w == v {
                    break;
                }
            }
            scc.sort_unstable();
            t.out.push(scc);
        }
    }
    let n = next.len();
    let mut t = T {
        next,
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        count: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() {
            visit(&mut t, v);
        }
    }
    t.out.sort();
    t.out
}

/// `[start, …, start]`, the fewest hops inside `inside`.
fn shortest_cycle(
    start: usize,
    next: &[Vec<usize>],
    inside: &BTreeSet<usize>,
) -> Option<Vec<usize>> {
    let mut from = BTreeMap::new();
    let mut queue = VecDeque::new();
    for &w in &next[start] {
        if inside.contains(&w) && !from.contains_key(&w) {
            from.insert(w, start);
            queue.push_back(w);
        }
    }
    while let Some(v) = queue.pop_front() {
        if v == start {
            let mut path = vec![start];
            let mut at = from[&start];
            while at != start {
                path.push(at);
                at = from[&at];
            }
            path.push(start);
            path.reverse();
            return Some(path);
        }
        for &w in &next[v] {
            if inside.contains(&w) && !from.contains_key(&w) {
                from.insert(w, v);
                queue.push_back(w);
            }
        }
    }
    None
}

/// `cli` and `tui` never import each other; no tab imports another tab.
fn fronts_and_tabs(modules: &[Module], edges: &Edges) -> Vec<String> {
    let mut out = Vec::new();
    for (&(a, b), (file, line, path)) in edges {
        let (ma, mb) = (&modules[a], &modules[b]);
        if ma.krate != mb.krate || ma.library {
            continue;
        }
        let top = |m: &Module| m.path.first().cloned().unwrap_or_default();
        let (ta, tb) = (top(ma), top(mb));
        if (ta == "cli" && tb == "tui") || (ta == "tui" && tb == "cli") {
            out.push(format!(
                "{ta} imports {tb}: {file}:{line} `{path}` ({} → {})",
                ma.name(),
                mb.name()
            ));
        }
        let tab = |m: &Module| match m.path.as_slice() {
            [t, tabs, name, ..] if t == "tui" && tabs == "tabs" => Some(name.clone()),
            _ => None,
        };
        if let (Some(x), Some(y)) = (tab(ma), tab(mb))
            && x != y
        {
            out.push(format!(
                "the {x} tab imports the {y} tab: {file}:{line} `{path}` ({} → {})",
                ma.name(),
                mb.name()
            ));
        }
    }
    out
}

/// A flag as the command line spells it: `--` and a letter, not inside a
/// longer run of dashes.
fn names_a_flag(s: &str) -> Option<String> {
    let b = s.as_bytes();
    (0..b.len().saturating_sub(2)).find_map(|i| {
        let starts = b[i] == b'-' && b[i + 1] == b'-' && b[i + 2].is_ascii_lowercase();
        let alone = i == 0 || !(b[i - 1] == b'-' || b[i - 1].is_ascii_alphanumeric());
        (starts && alone).then(|| {
            let end = (i + 2..b.len())
                .find(|&j| !(b[j].is_ascii_alphanumeric() || b[j] == b'-'))
                .unwrap_or(b.len());
            s[i..end].to_string()
        })
    })
}

/// The library knows no terminal: no ratatui or crossterm, no printing, no
/// command-line flag in its strings.
fn library_rules(
    modules: &[Module],
    files: &BTreeMap<String, String>,
    crates: &[Crate],
) -> Vec<String> {
    let mut out = Vec::new();
    for c in crates.iter().filter(|c| c.library) {
        let manifest = format!("{}/Cargo.toml", dir_of(dir_of(c.root)));
        if let Some(text) = files.get(&manifest) {
            for (i, l) in text.lines().enumerate() {
                let name = l.trim_start().split([' ', '=', '.']).next().unwrap_or("");
                if name == "ratatui" || name == "crossterm" {
                    out.push(format!(
                        "the library depends on {name}: {manifest}:{}",
                        i + 1
                    ));
                }
            }
        }
    }
    for m in modules.iter().filter(|m| m.library) {
        let written = m
            .uses
            .iter()
            .map(|(_, p, l)| (p, *l))
            .chain(m.refs.iter().map(|(p, l)| (p, *l)));
        let mut seen = BTreeSet::new();
        for (segs, line) in written {
            let first = segs.first().map(String::as_str).unwrap_or("");
            if (first == "ratatui" || first == "crossterm") && seen.insert(line) {
                out.push(format!(
                    "the library uses {first}: {}:{line} `{}`",
                    m.file,
                    segs.join("::")
                ));
            }
            let io = segs.len() >= 2 && segs[segs.len() - 2] == "io";
            let last = segs.last().map(String::as_str).unwrap_or("");
            if io && (last == "stdout" || last == "stderr") && seen.insert(line) {
                out.push(format!(
                    "the library writes to {last}: {}:{line} `{}`",
                    m.file,
                    segs.join("::")
                ));
            }
        }
        for (name, line) in &m.prints {
            out.push(format!("the library prints: {}:{line} `{name}!`", m.file));
        }
        let mut strings: Vec<&(String, usize)> = m.strings.iter().collect();
        strings.sort_by_key(|(_, l)| *l);
        strings.dedup();
        for (s, line) in strings {
            if let Some(flag) = names_a_flag(s) {
                let shown: String = s.chars().take(70).collect();
                let more = if s.chars().count() > 70 { "…" } else { "" };
                out.push(format!(
                    "a library string names the flag {flag}: {}:{line} {shown:?}{more}",
                    m.file
                ));
            }
        }
    }
    out
}

/// No non-test source file over [`MAX_LINES`], pure tables aside.
fn long_files(files: &BTreeMap<String, String>, module_files: &BTreeSet<String>) -> Vec<String> {
    module_files
        .iter()
        .filter(|f| !PURE_TABLES.iter().any(|(p, _)| p == f))
        .filter_map(|f| {
            let n = files[f].lines().count();
            (n > MAX_LINES).then(|| format!("{f}: {n} lines (at most {MAX_LINES})"))
        })
        .collect()
}
