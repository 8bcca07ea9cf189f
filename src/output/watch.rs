//! What `watch` shows: every point with its value, minimum, maximum, a trend of its recent
//! values and when it last changed, and the line's statistics; drawn with ratatui.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use ratatui::layout::{Constraint, Layout};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Cell, Paragraph, Row, Table, Wrap};
use ratatui::Frame;

use mbtool_core::master::failover::Left;
use mbtool_core::master::run::PollStats;
use mbtool_core::model::map::Point;
use mbtool_core::model::values::Value;

/// Values kept for a point's trend.
const TREND: usize = 24;

/// How long a changed value stays highlighted.
const HIGHLIGHT: Duration = Duration::from_secs(2);

const BARS: [char; 8] = ['▁', '▂', '▃', '▄', '▅', '▆', '▇', '█'];

struct PointView {
    name: String,
    reference: String,
    unit: String,
    value: Option<Value>,
    min: Option<f64>,
    max: Option<f64>,
    trend: VecDeque<f64>,
    changed: Option<Instant>,
}

fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Unsigned(v) => Some(*v as f64),
        Value::Signed(v) => Some(*v as f64),
        Value::Float32(v) => Some(f64::from(*v)),
        Value::Float(v) | Value::Decimal(v, _) => Some(*v),
        Value::Text(_) => None,
    }
}

/// Everything watch shows.
pub struct WatchState {
    title: String,
    points: Vec<PointView>,
    pub stats: PollStats,
    pub paused: bool,
    last_error: Option<String>,
}

impl WatchState {
    pub fn new(title: String, points: &[Point]) -> Self {
        Self {
            title,
            points: points
                .iter()
                .map(|p| PointView {
                    name: p.name.clone(),
                    reference: p.reference(),
                    unit: p.unit.clone(),
                    value: None,
                    min: None,
                    max: None,
                    trend: VecDeque::with_capacity(TREND),
                    changed: None,
                })
                .collect(),
            stats: PollStats::default(),
            paused: false,
            last_error: None,
        }
    }

    /// A poll's values, by point index.
    pub fn update(&mut self, values: Vec<(usize, Value)>) {
        self.last_error = None;
        if self.paused {
            return;
        }
        let now = Instant::now();
        for (index, value) in values {
            let Some(view) = self.points.get_mut(index) else {
                continue;
            };
            if view.value.as_ref().is_some_and(|old| *old != value) {
                view.changed = Some(now);
            }
            if let Some(x) = number(&value) {
                view.min = Some(view.min.map_or(x, |m| m.min(x)));
                view.max = Some(view.max.map_or(x, |m| m.max(x)));
                if view.trend.len() == TREND {
                    view.trend.pop_front();
                }
                view.trend.push_back(x);
            }
            view.value = Some(value);
        }
    }

    pub fn failed(&mut self, error: String) {
        self.last_error = Some(error);
    }

    /// The master changed paths: the title says which one is read now, and why; how
    /// the request that made the change ended on the path left is counted.
    pub fn switched(&mut self, title: String, left: Option<Left>) {
        self.stats.switches += 1;
        if let Some(left) = left {
            self.stats.record_left(left);
        }
        self.title = title;
    }

    /// `r`: minimum, maximum and trends start again.
    pub fn reset(&mut self) {
        for view in &mut self.points {
            view.min = None;
            view.max = None;
            view.trend.clear();
        }
    }

    pub fn render(&self, frame: &mut Frame) {
        let state = match (&self.last_error, self.paused) {
            (_, true) => "PAUSED (p resumes)".to_string(),
            (Some(error), false) => error.clone(),
            (None, false) => String::new(),
        };
        // The counts, the response times and the keys each on a line of their own.
        let summary = self.stats.summary();
        let status_lines: Vec<String> = summary
            .split("; ")
            .map(String::from)
            .chain([format!("q quit  p pause  r reset   {state}")])
            .collect();
        // The status wraps rather than being cut off: as many rows as it takes inside the
        // border, up to half the screen.
        let inner = usize::from(frame.area().width.saturating_sub(2)).max(1);
        let rows: usize = status_lines
            .iter()
            .map(|line| line.chars().count().div_ceil(inner).max(1))
            .sum();
        let height = u16::try_from(rows + 2)
            .unwrap_or(u16::MAX)
            .min(frame.area().height / 2)
            .max(4);
        let [table_area, status_area] =
            Layout::vertical([Constraint::Min(3), Constraint::Length(height)]).areas(frame.area());
        let now = Instant::now();
        let rows = self.points.iter().map(|view| {
            let shown = |x: Option<f64>| x.map(|v| Value::Float(v).to_string()).unwrap_or_default();
            let value = match (&view.value, view.unit.as_str()) {
                (Some(value), "") => value.to_string(),
                (Some(value), unit) => format!("{value} {unit}"),
                (None, _) => "-".into(),
            };
            let recent = view
                .changed
                .is_some_and(|at| now.duration_since(at) < HIGHLIGHT);
            let value_style = if recent {
                Style::default().add_modifier(Modifier::REVERSED)
            } else {
                Style::default()
            };
            let changed = view.changed.map_or("-".into(), |at| {
                format!("{:.0} s ago", now.duration_since(at).as_secs_f64())
            });
            Row::new(vec![
                Cell::from(view.name.clone()),
                Cell::from(view.reference.clone()),
                Cell::from(value).style(value_style),
                Cell::from(shown(view.min)),
                Cell::from(shown(view.max)),
                Cell::from(sparkline(&view.trend)),
                Cell::from(changed),
            ])
        });
        let header = Row::new(["name", "ref", "value", "min", "max", "trend", "changed"])
            .style(Style::default().add_modifier(Modifier::BOLD));
        // The trend and the time since a change give way first on a narrow terminal.
        let wide = table_area.width >= 80;
        let widths = [
            Constraint::Min(8),
            Constraint::Length(10),
            Constraint::Min(15),
            Constraint::Min(8),
            Constraint::Min(8),
            Constraint::Length(if wide { TREND as u16 } else { 0 }),
            Constraint::Length(if wide { 9 } else { 0 }),
        ];
        // Rows past the bottom are said in the title: the border, header and border take 3.
        let shown = usize::from(table_area.height.saturating_sub(3));
        let title = match self.points.len() {
            n if n > shown => format!(
                "{}(showing {shown} of {n}: make the terminal taller) ",
                self.title
            ),
            _ => self.title.clone(),
        };
        let table = Table::new(rows, widths)
            .header(header)
            .block(Block::bordered().title(title));
        frame.render_widget(table, table_area);
        let status = Paragraph::new(status_lines.into_iter().map(Line::from).collect::<Vec<_>>())
            .wrap(Wrap { trim: true })
            .block(Block::bordered());
        frame.render_widget(status, status_area);
    }
}

/// Recent values as bars, lowest to highest of those shown.
fn sparkline(values: &VecDeque<f64>) -> String {
    let low = values.iter().copied().fold(f64::INFINITY, f64::min);
    let high = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    values
        .iter()
        .map(|v| {
            let share = if high > low {
                (v - low) / (high - low)
            } else {
                0.5
            };
            BARS[((share * 7.0).round() as usize).min(7)]
        })
        .collect()
}
