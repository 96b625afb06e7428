//! The URDF document read into links and joints, every value exact (`0.4318` is 4318/10000)
//! and every element with its 1-based line and column, so that later steps can point into the
//! file. Only what the dynamics need is read: `<inertial>` of links, and of joints their type,
//! parent, child, `<origin>`, `<axis>`, `<dynamics>` and `<mimic>`; and `<limit>`, for the
//! trajectories a command line tool plans ([`super::joint_limits`]).

use crate::front::errors::FileError;
use crate::front::sources::At;
use crate::model::{Placement, Value};
use crate::symbolic::Number;
use roxmltree::Node;

/// A link's `<inertial>`: mass, centre of mass and inertia tensor (about the centre of mass,
/// in the axes `rpy` turns the link frame to).
pub(super) struct Inertial {
    pub mass: Value,
    /// `<origin>`: the centre of mass (`xyz`) and the inertia's axes (`rpy`).
    pub origin: Placement,
    /// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`, tensor entries as URDF writes them.
    pub inertia: [Value; 6],
    pub mass_at: At,
    pub inertia_at: At,
}

/// A `<link>`.
pub(super) struct Link {
    pub name: String,
    pub at: At,
    pub inertial: Option<Inertial>,
}

/// A joint's `type`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Revolute,
    Continuous,
    Prismatic,
    Fixed,
    Floating,
    Planar,
}

impl Kind {
    /// Whether the joint has a variable: everything but `fixed`.
    pub fn moves(self) -> bool {
        self != Kind::Fixed
    }
}

/// A `<joint>`.
pub(super) struct Joint {
    pub name: String,
    pub kind: Kind,
    pub at: At,
    pub parent: String,
    pub child: String,
    /// `<origin>`: the joint frame in the parent link's frame.
    pub origin: Placement,
    /// `<axis xyz>`, `[1, 0, 0]` when absent.
    pub axis: [Value; 3],
    pub axis_at: At,
    /// `<dynamics damping>` and `friction`, each with where it is written.
    pub damping: Option<(Value, At)>,
    pub friction: Option<(Value, At)>,
    /// `<mimic>`, if the joint has one.
    pub mimic: Option<Mimic>,
    /// `<limit lower upper velocity effort>`, each where it is written.
    pub limit: Limit,
}

/// A joint's `<mimic joint multiplier offset>` (defaults 1 and 0): it follows
/// `q = multiplier · q_joint + offset`.
pub(super) struct Mimic {
    pub joint: String,
    pub multiplier: Value,
    pub offset: Value,
    pub at: At,
}

/// A joint's `<limit>`: the attributes the file writes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Limit {
    /// The range of the joint variable (rad or m).
    pub lower: Option<f64>,
    pub upper: Option<f64>,
    /// The largest speed (rad/s or m/s).
    pub velocity: Option<f64>,
    /// The largest torque or force (N·m or N): the rated torque of `simplify(...)`'s
    /// `tolerance_percent` when no `rated` is given.
    pub effort: Option<f64>,
}

/// The `<robot>`: its name, links and joints in the file's order.
pub(super) struct Description {
    pub name: Option<String>,
    pub at: At,
    pub links: Vec<Link>,
    pub joints: Vec<Joint>,
}

/// Reads the robot; the XML's first syntax error, or every element that cannot be read.
pub(super) fn read(text: &str) -> Result<Description, Vec<FileError>> {
    let doc = roxmltree::Document::parse(text).map_err(|e| vec![malformed(&e)])?;
    let root = doc.root_element();
    let reader = Reader {
        text: text.as_bytes(),
        lines: Lines::new(text),
    };
    // Before anything else: the macros of a xacro file hold its links and joints, so that
    // every other error would be beside the point.
    if let Some(element) = doc.descendants().find(|n| is_xacro(n)) {
        let tag = element.tag_name();
        let prefix = tag.namespace().and_then(|uri| element.lookup_prefix(uri));
        let written = format!("`<{}:{}>`", prefix.unwrap_or("xacro"), tag.name());
        return Err(vec![error(reader.at(element), unexpanded(&written))]);
    }
    if root.tag_name().name() != "robot" {
        let found = root.tag_name().name();
        return Err(vec![error(
            reader.at(root),
            format!("the root element is `<{found}>`: a URDF file has `<robot>`"),
        )]);
    }
    let mut errors = Vec::new();
    let elements = |name: &'static str| root.children().filter(move |n| n.has_tag_name(name));
    let links: Vec<Link> = elements("link")
        .filter_map(|n| reader.link(n).map_err(|e| errors.push(e)).ok())
        .collect();
    let joints: Vec<Joint> = elements("joint")
        .filter_map(|n| reader.joint(n).map_err(|e| errors.push(e)).ok())
        .collect();
    if !errors.is_empty() {
        return Err(errors);
    }
    Ok(Description {
        name: root.attribute("name").map(str::to_string),
        at: reader.at(root),
        links,
        joints,
    })
}

/// The XML's syntax error as the file's error, at its place.
fn malformed(e: &roxmltree::Error) -> FileError {
    let pos = e.pos();
    let at = (pos.row as usize, pos.col as usize);
    // `xacro:` elements without the namespace declared: a xacro file all the same.
    if let roxmltree::Error::UnknownNamespace(prefix, _) = e {
        if prefix == "xacro" {
            return error(at, unexpanded("a `xacro:` element"));
        }
    }
    let message = e.to_string();
    // roxmltree ends its messages with the position, which the error carries already.
    let message = message
        .strip_suffix(&format!(" at {pos}"))
        .unwrap_or(&message);
    error(at, format!("malformed XML: {message}"))
}

/// An element of the xacro namespace (`<xacro:macro>`, `<xacro:include>`, ..). An expanded
/// file may keep the namespace's declaration on `<robot>`, but none of its elements.
fn is_xacro(node: &Node) -> bool {
    node.is_element()
        && node
            .tag_name()
            .namespace()
            .is_some_and(|uri| uri.trim_end_matches('/').ends_with("xacro"))
}

/// The error for a xacro file, which `written` shows to be one.
fn unexpanded(written: &str) -> String {
    format!("{written}: this is a xacro file, not a URDF: expand it with `xacro` first (`xacro robot.urdf.xacro > robot.urdf`) and use the URDF it writes")
}

/// A message at a place in the file.
pub(super) fn error(at: At, message: impl Into<String>) -> FileError {
    FileError {
        message: message.into(),
        line: Some(at.0),
        column: Some(at.1),
        about: None,
    }
}

/// Bytes between the checkpoints of [`Lines`]: each position counts at most this many.
const STRIDE: usize = 64;

/// The line and column of each byte offset, as roxmltree counts them (lines after `\n`,
/// columns in characters), found in constant time: roxmltree's `text_pos_at` counts from the
/// start of the text, which made reading a file of many elements quadratic.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Lines {
    /// The offset where each line starts.
    starts: Vec<usize>,
    /// The characters before each multiple of [`STRIDE`] bytes.
    chars: Vec<usize>,
}

impl Lines {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn new(text: &str) -> Lines {
        let bytes = text.as_bytes();
        let starts = std::iter::once(0)
            .chain(
                bytes
                    .iter()
                    .enumerate()
                    .filter(|(_, b)| **b == b'\n')
                    .map(|(i, _)| i + 1),
            )
            .collect();
        let chars = std::iter::once(0)
            .chain(bytes.chunks(STRIDE).scan(0, |n, chunk| {
                *n += starts_char(chunk);
                Some(*n)
            }))
            .collect();
        Lines { starts, chars }
    }

    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn at(&self, text: &[u8], offset: usize) -> At {
        let line = self.starts.partition_point(|start| *start <= offset);
        let start = self.starts[line - 1];
        let chars_before = |offset: usize| {
            let k = offset / STRIDE;
            self.chars[k] + starts_char(&text[k * STRIDE..offset])
        };
        (line, chars_before(offset) - chars_before(start) + 1)
    }
}

/// The characters that start in `bytes` (every byte but UTF-8's continuation bytes).
fn starts_char(bytes: &[u8]) -> usize {
    bytes.iter().filter(|b| **b & 0xC0 != 0x80).count()
}

struct Reader<'a> {
    text: &'a [u8],
    lines: Lines,
}

impl Reader<'_> {
    fn at(&self, node: Node) -> At {
        self.offset(node.range().start)
    }

    fn offset(&self, offset: usize) -> At {
        self.lines.at(self.text, offset)
    }

    /// The first child element `name` of `node`.
    fn child<'a, 'input>(node: Node<'a, 'input>, name: &str) -> Option<Node<'a, 'input>> {
        node.children().find(|n| n.has_tag_name(name))
    }

    /// Attribute `name` of `node`; an error at the element if it is missing.
    fn required<'a>(&self, node: Node<'a, '_>, name: &str) -> Result<&'a str, FileError> {
        node.attribute(name).ok_or_else(|| {
            let tag = node.tag_name().name();
            error(
                self.at(node),
                format!("`<{tag}>` has no `{name}` attribute"),
            )
        })
    }

    /// Where the value of `attr` starts, after its quote: roxmltree's `range_value` counts at
    /// most 255 spaces around the `=`, and starts the value too early past them.
    fn value_start(&self, attr: &roxmltree::Attribute) -> usize {
        let name_end = attr.range_qname().end;
        self.text[name_end..]
            .iter()
            .position(|b| matches!(b, b'"' | b'\''))
            .map_or(name_end, |quote| name_end + quote + 1)
    }

    /// `N` numbers in attribute `name` of `node` (`default` where it is absent), and where
    /// they are written.
    fn numbers<const N: usize>(
        &self,
        node: Node,
        name: &str,
        default: [&str; N],
    ) -> Result<([Value; N], At), FileError> {
        let Some(attr) = node.attribute_node(name) else {
            return Ok((
                default.map(|d| number(d).unwrap_or_default()),
                self.at(node),
            ));
        };
        let at = self.offset(self.value_start(&attr));
        let words: Vec<&str> = attr.value().split_whitespace().collect();
        let parsed: Option<Vec<Value>> = words.iter().map(|w| number(w)).collect();
        match parsed.map(<[Value; N]>::try_from) {
            Some(Ok(values)) => Ok((values, at)),
            _ => {
                let tag = node.tag_name().name();
                let what = if N == 1 { "a number" } else { "numbers" };
                let value = attr.value();
                Err(error(
                    at,
                    format!("`<{tag} {name}=\"{value}\">`: expected {N} {what}"),
                ))
            }
        }
    }

    /// An `<origin xyz rpy>` child of `node`, the identity where absent.
    fn origin(&self, node: Node) -> Result<Placement, FileError> {
        let Some(origin) = Self::child(node, "origin") else {
            return Ok(Placement::default());
        };
        let (xyz, _) = self.numbers(origin, "xyz", ["0"; 3])?;
        let (rpy, _) = self.numbers(origin, "rpy", ["0"; 3])?;
        Ok(Placement { xyz, rpy })
    }

    fn link(&self, node: Node) -> Result<Link, FileError> {
        let name = self.required(node, "name")?.to_string();
        let inertial = match Self::child(node, "inertial") {
            Some(inertial) => Some(self.inertial(inertial)?),
            None => None,
        };
        Ok(Link {
            name,
            at: self.at(node),
            inertial,
        })
    }

    fn inertial(&self, node: Node) -> Result<Inertial, FileError> {
        let missing = |what: &str| error(self.at(node), format!("`<inertial>` has no `<{what}>`"));
        let mass = Self::child(node, "mass").ok_or_else(|| missing("mass"))?;
        let inertia = Self::child(node, "inertia").ok_or_else(|| missing("inertia"))?;
        let ([mass_value], mass_at) = self.numbers(mass, "value", ["0"])?;
        let mut entries: [Value; 6] = Default::default();
        let mut inertia_at = self.at(inertia);
        for (slot, key) in ["ixx", "iyy", "izz", "ixy", "ixz", "iyz"]
            .iter()
            .enumerate()
        {
            let ([value], at) = self.numbers(inertia, key, ["0"])?;
            if slot == 0 {
                inertia_at = at;
            }
            entries[slot] = value;
        }
        Ok(Inertial {
            mass: mass_value,
            origin: self.origin(node)?,
            inertia: entries,
            mass_at,
            inertia_at,
        })
    }

    fn joint(&self, node: Node) -> Result<Joint, FileError> {
        let at = self.at(node);
        let name = self.required(node, "name")?.to_string();
        let kind = match self.required(node, "type")? {
            "revolute" => Kind::Revolute,
            "continuous" => Kind::Continuous,
            "prismatic" => Kind::Prismatic,
            "fixed" => Kind::Fixed,
            "floating" => Kind::Floating,
            "planar" => Kind::Planar,
            other => {
                return Err(error(at, format!("joint `{name}` has the unknown type `{other}`: expected revolute, continuous, prismatic, fixed, floating or planar")));
            }
        };
        let link_of = |what: &str| -> Result<String, FileError> {
            let element = Self::child(node, what).ok_or_else(|| {
                error(at, format!("joint `{name}` has no `<{what} link=\"..\"/>`"))
            })?;
            Ok(self.required(element, "link")?.to_string())
        };
        let (parent, child) = (link_of("parent")?, link_of("child")?);
        let (axis, axis_at) = match Self::child(node, "axis") {
            Some(axis) => self.numbers(axis, "xyz", ["1", "0", "0"])?,
            None => ([1, 0, 0].map(|x| Value::num(Number::int(x))), at),
        };
        let dynamics = Self::child(node, "dynamics");
        let coefficient = |key: &str| -> Result<Option<(Value, At)>, FileError> {
            match dynamics.filter(|d| d.has_attribute(key)) {
                Some(d) => self.numbers(d, key, ["0"]).map(|([v], at)| Some((v, at))),
                None => Ok(None),
            }
        };
        Ok(Joint {
            limit: self.limit(node)?,
            origin: self.origin(node)?,
            damping: coefficient("damping")?,
            friction: coefficient("friction")?,
            mimic: match Self::child(node, "mimic") {
                Some(m) => Some(Mimic {
                    joint: self.required(m, "joint")?.to_string(),
                    multiplier: self.numbers(m, "multiplier", ["1"])?.0[0].clone(),
                    offset: self.numbers(m, "offset", ["0"])?.0[0].clone(),
                    at: self.at(m),
                }),
                None => None,
            },
            name,
            kind,
            at,
            parent,
            child,
            axis,
            axis_at,
        })
    }

    /// The `<limit>` child of a joint, if any; a value that is not a number is an error at it.
    fn limit(&self, node: Node) -> Result<Limit, FileError> {
        let Some(limit) = Self::child(node, "limit") else {
            return Ok(Limit::default());
        };
        let value = |key: &str| -> Result<Option<f64>, FileError> {
            if !limit.has_attribute(key) {
                return Ok(None);
            }
            let ([v], _) = self.numbers(limit, key, ["0"])?;
            Ok(v.eval(&|_| None))
        };
        Ok(Limit {
            lower: value("lower")?,
            upper: value("upper")?,
            velocity: value("velocity")?,
            effort: value("effort")?,
        })
    }
}

/// A URDF number (`-0.4318`, `1e-15`, `+2`) as an exact value.
fn number(text: &str) -> Option<Value> {
    let text = text.strip_prefix('+').unwrap_or(text);
    if let Some(n) = Number::parse_decimal(text) {
        return Some(Value::num(n));
    }
    // Too many digits for a rational: the nearest float.
    text.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .map(Value::from_f64)
}
