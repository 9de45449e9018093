//! The crate's recorded camera paths (`paths/*.json`, docs/paths.md) read for the budget test:
//! a minimal JSON reader (the files are plain objects, arrays, numbers and strings), so that the
//! test needs no JSON crate in this workspace.
#![allow(dead_code)]

use std::collections::BTreeMap;

/// A JSON value.
#[derive(Debug, Clone)]
pub enum Json {
    Null,
    Bool(bool),
    Num(f64),
    Str(String),
    Arr(Vec<Json>),
    Obj(BTreeMap<String, Json>),
}

impl Json {
    pub fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Obj(m) => m.get(key),
            _ => None,
        }
    }
    pub fn num(&self) -> f64 {
        match self {
            Json::Num(x) => *x,
            other => panic!("not a number: {other:?}"),
        }
    }
    pub fn arr(&self) -> &[Json] {
        match self {
            Json::Arr(a) => a,
            other => panic!("not an array: {other:?}"),
        }
    }
    pub fn vec3(&self) -> [f64; 3] {
        let a = self.arr();
        assert_eq!(a.len(), 3, "a 3-vector");
        [a[0].num(), a[1].num(), a[2].num()]
    }
}

struct Reader<'a> {
    s: &'a [u8],
    i: usize,
}

impl Reader<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }
    fn eat(&mut self, c: u8) {
        self.ws();
        assert_eq!(
            self.s.get(self.i),
            Some(&c),
            "expected {:?} at {}",
            c as char,
            self.i
        );
        self.i += 1;
    }
    fn string(&mut self) -> String {
        self.eat(b'"');
        let start = self.i;
        while self.s[self.i] != b'"' {
            assert_ne!(
                self.s[self.i], b'\\',
                "escapes are not used in the path files"
            );
            self.i += 1;
        }
        self.i += 1;
        String::from_utf8(self.s[start..self.i - 1].to_vec()).expect("UTF-8")
    }
    fn value(&mut self) -> Json {
        self.ws();
        match self.s[self.i] {
            b'{' => {
                self.i += 1;
                let mut m = BTreeMap::new();
                self.ws();
                if self.s[self.i] == b'}' {
                    self.i += 1;
                    return Json::Obj(m);
                }
                loop {
                    let k = self.string();
                    self.eat(b':');
                    m.insert(k, self.value());
                    self.ws();
                    self.i += 1;
                    match self.s[self.i - 1] {
                        b',' => {}
                        b'}' => return Json::Obj(m),
                        c => panic!("unexpected {:?} in an object", c as char),
                    }
                }
            }
            b'[' => {
                self.i += 1;
                let mut a = Vec::new();
                self.ws();
                if self.s[self.i] == b']' {
                    self.i += 1;
                    return Json::Arr(a);
                }
                loop {
                    a.push(self.value());
                    self.ws();
                    self.i += 1;
                    match self.s[self.i - 1] {
                        b',' => {}
                        b']' => return Json::Arr(a),
                        c => panic!("unexpected {:?} in an array", c as char),
                    }
                }
            }
            b'"' => Json::Str(self.string()),
            b't' | b'f' | b'n' => {
                for (word, v) in [
                    ("true", Json::Bool(true)),
                    ("false", Json::Bool(false)),
                    ("null", Json::Null),
                ] {
                    if self.s[self.i..].starts_with(word.as_bytes()) {
                        self.i += word.len();
                        return v;
                    }
                }
                panic!("unexpected literal at {}", self.i)
            }
            _ => {
                let start = self.i;
                while self.i < self.s.len()
                    && matches!(
                        self.s[self.i],
                        b'0'..=b'9' | b'-' | b'+' | b'.' | b'e' | b'E'
                    )
                {
                    self.i += 1;
                }
                let t = std::str::from_utf8(&self.s[start..self.i]).expect("ASCII");
                Json::Num(t.parse().unwrap_or_else(|_| panic!("bad number {t:?}")))
            }
        }
    }
}

/// Parses a JSON text (panics on malformed input: the files are the repository's own).
pub fn parse(text: &str) -> Json {
    let mut r = Reader {
        s: text.as_bytes(),
        i: 0,
    };
    let v = r.value();
    r.ws();
    assert_eq!(r.i, text.len(), "trailing text after the JSON value");
    v
}

/// One frame of a path.
#[derive(Debug, Clone, Copy)]
pub struct PathFrame {
    pub eye: [f64; 3],
    pub target: [f64; 3],
    pub light_dir: [f64; 3],
}

/// A camera path: the projection, the scene's boxes and the frames.
#[derive(Debug, Clone)]
pub struct CameraPath {
    pub name: String,
    pub image_height: u32,
    pub near: f64,
    pub far: f64,
    pub half_fov: f64,
    pub aspect: f64,
    pub receivers: Vec<[f64; 6]>,
    pub casters: Vec<[f64; 6]>,
    pub frames: Vec<PathFrame>,
}

fn boxes(v: Option<&Json>) -> Vec<[f64; 6]> {
    v.map_or(Vec::new(), |a| {
        a.arr()
            .iter()
            .map(|b| {
                let b = b.arr();
                assert_eq!(b.len(), 6, "a box is six numbers");
                std::array::from_fn(|i| b[i].num())
            })
            .collect()
    })
}

/// Reads `paths/<name>.json` of the repository (two folders up from this workspace).
pub fn read(name: &str) -> CameraPath {
    let file = format!("{}/../../paths/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{file}: {e}"));
    let j = parse(&text);
    let camera = j.get("camera").expect("camera");
    let scene = j.get("scene").expect("scene");
    let light = j.get("light_dir").map(Json::vec3);
    let frames = j
        .get("frames")
        .expect("frames")
        .arr()
        .iter()
        .map(|f| PathFrame {
            eye: f.get("eye").expect("eye").vec3(),
            target: f.get("target").expect("target").vec3(),
            light_dir: f
                .get("light_dir")
                .map(Json::vec3)
                .or(light)
                .expect("a light for every frame"),
        })
        .collect();
    CameraPath {
        name: name.to_string(),
        image_height: j.get("image_height").expect("image_height").num() as u32,
        near: camera.get("near").expect("near").num(),
        far: camera.get("far").expect("far").num(),
        half_fov: camera.get("half_fov").expect("half_fov").num(),
        aspect: camera.get("aspect").expect("aspect").num(),
        receivers: boxes(scene.get("receivers")),
        casters: boxes(scene.get("casters")),
        frames,
    }
}
