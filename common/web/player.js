// The kit's 3D simulation player: turns the JSON header and compressed blobs that a C++
// writer embeds in one self-contained HTML page into an interactive three.js view.
// The format is the writer's (common/src/render/web_page.cpp, page_blob.hpp): a JSON header in
// <script id="kit-data">, blobs as base64 zlib streams, one pane per compared run. Tests read
// #kit-frame, #kit-time, the .kit-readout outputs and body[data-kit-ready] (tests/browser/).
// Plain ES2017 in one IIFE because the page is opened from file:// with no modules.
(function () {
  'use strict';

  const SPEEDS = [0.25, 0.5, 1, 2, 4];

  // ---- Small DOM helpers ----

  function el(tag, className, text) {
    const node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function append(parent, ...children) {
    for (const child of children) parent.appendChild(child);
    return parent;
  }

  // Reports a failure in every place a reader or a test would look for it.
  function fail(message, explanation) {
    document.body.dataset.kitReady = 'error: ' + message;
    console.error('kit player: ' + message);
    const box = el('div', 'kit-error', explanation || 'The player could not show this page: ' + message);
    document.body.insertBefore(box, document.body.firstChild);
  }

  // ---- Blob decoding: base64 -> zlib (RFC 1950) -> little-endian typed arrays ----

  async function inflateBase64(text) {
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    // 'deflate' in DecompressionStream means the zlib wrapper, which is what the writer emits.
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
    return new Response(stream).arrayBuffer();
  }

  // Typed array views need aligned offsets and the platform's byte order; every browser
  // that runs WebGL is little-endian, like the writer, so a direct view is safe.
  async function decodeArray(text, Type, expectedLength, what) {
    let buffer;
    try {
      buffer = await inflateBase64(text);
    } catch (error) {
      // The browser's own message here ("Failed to fetch") says nothing about the cause.
      throw new Error(what + ' is not a valid base64 zlib stream (' + error.message + ')');
    }
    const array = new Type(buffer);
    if (array.length !== expectedLength) {
      throw new Error(what + ' holds ' + array.length + ' values, expected ' + expectedLength);
    }
    return array;
  }

  // Mesh positions are delta-coded between frames (frame 0 absolute) so that zlib sees
  // small numbers; undo that in place, modulo 2^16 as the writer wraps.
  function undoDeltaCoding(q, valuesPerFrame, frames) {
    for (let f = 1; f < frames; f++) {
      const here = f * valuesPerFrame;
      const before = here - valuesPerFrame;
      for (let i = 0; i < valuesPerFrame; i++) q[here + i] = (q[before + i] + q[here + i]) & 0xffff;
    }
  }

  // Writes quantised positions q[first .. first+3*count) as metres into out.
  function dequantise(q, first, count, box, out) {
    const scale = [0, 1, 2].map((a) => (box[a + 3] - box[a]) / 65535);
    for (let i = 0; i < count * 3; i++) {
      const axis = i % 3;
      out[i] = box[axis] + q[first + i] * scale[axis];
    }
  }

  async function decodeObject(object) {
    const data = {};
    if (object.type === 'mesh') {
      const V = object.vertices;
      data.indices = await decodeArray(object.indices, Uint32Array, 3 * object.triangles, object.name + ' indices');
      data.q = await decodeArray(object.positions, Uint16Array, object.frames * V * 3, object.name + ' positions');
      undoDeltaCoding(data.q, V * 3, object.frames);
      if (object.scalar) {
        data.scalar = await decodeArray(object.scalar.values, Uint8Array, object.frames * V, object.name + ' scalar');
      }
    } else if (object.type === 'points') {
      const total = object.counts.reduce((a, b) => a + b, 0);
      data.q = await decodeArray(object.positions, Uint16Array, total * 3, object.name + ' positions');
      data.rgba = await decodeArray(object.colors, Uint8Array, total * 4, object.name + ' colors');
      // Start of each frame's points, so scrubbing can jump anywhere.
      data.firstPoint = [];
      let running = 0;
      for (const count of object.counts) { data.firstPoint.push(running); running += count; }
      data.maxCount = Math.max(1, ...object.counts);
    }
    return data;
  }

  // ---- Colour map for scalar fields: viridis-like, perceptually ordered and readable on white ----

  const COLORMAP_STOPS = [
    [0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207, 0.372, 0.553],
    [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267, 0.749, 0.441],
    [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144],
  ];

  // 256 entries, one per stored uint8 level, so per-vertex colouring is a table lookup.
  // three r111 applies no output gamma by default, so these values match the CSS legend.
  function buildColormapTable() {
    const table = new Float32Array(256 * 3);
    const last = COLORMAP_STOPS.length - 1;
    for (let i = 0; i < 256; i++) {
      const x = (i / 255) * last;
      const k = Math.min(Math.floor(x), last - 1);
      const w = x - k;
      for (let c = 0; c < 3; c++) {
        table[3 * i + c] = COLORMAP_STOPS[k][c] * (1 - w) + COLORMAP_STOPS[k + 1][c] * w;
      }
    }
    return table;
  }
  const COLORMAP = buildColormapTable();

  function colormapCss() {
    const stops = COLORMAP_STOPS.map((c, i) => {
      const rgb = c.map((v) => Math.round(v * 255)).join(',');
      return 'rgb(' + rgb + ') ' + ((100 * i) / (COLORMAP_STOPS.length - 1)).toFixed(1) + '%';
    });
    return 'linear-gradient(to right, ' + stops.join(', ') + ')';
  }

  // ---- Scene objects: each returns {object3d, box, showFrame(f), setWireframe(on)} ----

  function makeMesh(spec, data) {
    const V = spec.vertices;
    const geometry = new THREE.BufferGeometry();
    const positions = new Float32Array(V * 3);
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(data.indices, 1));

    const material = new THREE.MeshStandardMaterial({
      // Under full light a white base would push the colour map past its top colour.
      color: data.scalar ? 0xd0d0d0 : spec.color || '#c8553d',
      roughness: 0.75,
      metalness: 0.0,
      side: THREE.DoubleSide, // cloth is seen from both sides
      flatShading: !!spec.flat,
    });
    let colors = null;
    if (data.scalar) {
      colors = new Float32Array(V * 3);
      geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
      material.vertexColors = THREE.VertexColors;
    }
    const mesh = new THREE.Mesh(geometry, material);
    // The vertices move every frame; a stale bounding sphere would cull the mesh wrongly.
    mesh.frustumCulled = false;
    const group = new THREE.Group();
    group.add(mesh);

    const pins = makePinMarkers(spec, group);

    function showFrame(f) {
      dequantise(data.q, f * V * 3, V, spec.box, positions);
      geometry.attributes.position.needsUpdate = true;
      if (!spec.flat) geometry.computeVertexNormals(); // flat shading derives its own normals
      if (colors) {
        const levels = data.scalar.subarray(f * V, (f + 1) * V);
        for (let i = 0; i < V; i++) colors.set(COLORMAP.subarray(3 * levels[i], 3 * levels[i] + 3), 3 * i);
        geometry.attributes.color.needsUpdate = true;
      }
      pins.forEach((marker, i) => marker.position.fromArray(positions, 3 * spec.pins[i]));
    }

    return {
      object3d: group,
      box: spec.box,
      showFrame,
      setWireframe(on) { material.wireframe = on; },
    };
  }

  // Pins are few; one small dark sphere each keeps them visible from any side.
  function makePinMarkers(spec, group) {
    if (!spec.pins || spec.pins.length === 0) return [];
    const b = spec.box;
    const extent = Math.max(b[3] - b[0], b[4] - b[1], b[5] - b[2]) || 1;
    const geometry = new THREE.SphereBufferGeometry(0.018 * extent, 16, 12);
    const material = new THREE.MeshStandardMaterial({ color: 0x222222, roughness: 0.5 });
    return spec.pins.map(() => {
      const marker = new THREE.Mesh(geometry, material);
      group.add(marker);
      return marker;
    });
  }

  // Round soft sprites with per-point alpha: PointsMaterial in r111 has no vertex alpha,
  // hence a small shader. Size is in world metres, so the point scales with distance.
  const POINT_VERTEX_SHADER = [
    'attribute vec4 rgba;',
    'uniform float size;',
    'uniform float pixelsPerUnit;',
    'varying vec4 vColor;',
    'void main() {',
    '  vColor = rgba;',
    '  vec4 mv = modelViewMatrix * vec4(position, 1.0);',
    '  gl_PointSize = max(1.0, size * pixelsPerUnit / -mv.z);',
    '  gl_Position = projectionMatrix * mv;',
    '}',
  ].join('\n');

  const POINT_FRAGMENT_SHADER = [
    'varying vec4 vColor;',
    'void main() {',
    '  float r = length(gl_PointCoord - vec2(0.5)) * 2.0;',
    '  if (r > 1.0) discard;',
    '  float edge = 1.0 - smoothstep(0.6, 1.0, r);',
    '  gl_FragColor = vec4(vColor.rgb, vColor.a * edge);',
    '}',
  ].join('\n');

  function makePoints(spec, data) {
    const geometry = new THREE.BufferGeometry();
    const positions = new Float32Array(data.maxCount * 3);
    const rgba = new Uint8Array(data.maxCount * 4);
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('rgba', new THREE.BufferAttribute(rgba, 4, true));
    const material = new THREE.ShaderMaterial({
      uniforms: { size: { value: spec.size || 0.05 }, pixelsPerUnit: { value: 500 } },
      vertexShader: POINT_VERTEX_SHADER,
      fragmentShader: POINT_FRAGMENT_SHADER,
      transparent: true,
      depthWrite: false, // soft overlapping sprites must not hide each other
    });
    const points = new THREE.Points(geometry, material);
    points.frustumCulled = false;

    function showFrame(f) {
      const first = data.firstPoint[f];
      const count = spec.counts[f];
      dequantise(data.q, 3 * first, count, spec.box, positions);
      rgba.set(data.rgba.subarray(4 * first, 4 * (first + count)));
      geometry.attributes.position.needsUpdate = true;
      geometry.attributes.rgba.needsUpdate = true;
      geometry.setDrawRange(0, count);
    }

    return {
      object3d: points,
      box: spec.box,
      showFrame,
      setWireframe() {},
      setPixelsPerUnit(value) { material.uniforms.pixelsPerUnit.value = value; },
    };
  }

  function makeSphere(spec) {
    // Drawn a hair smaller than stored: cloth resting on the surface (within the solver's
    // collision margin) would otherwise flicker through it.
    const radius = spec.radius * 0.985;
    const material = new THREE.MeshStandardMaterial({ color: spec.color || '#888888', roughness: 0.6 });
    const mesh = new THREE.Mesh(new THREE.SphereBufferGeometry(radius, 48, 32), material);
    mesh.position.fromArray(spec.center);
    const c = spec.center;
    const r = spec.radius;
    return {
      object3d: mesh,
      box: [c[0] - r, c[1] - r, c[2] - r, c[0] + r, c[1] + r, c[2] + r],
      showFrame() {},
      setWireframe(on) { material.wireframe = on; },
    };
  }

  function makeGround(spec) {
    const size = spec.size || 10;
    const group = new THREE.Group();
    // A grazing light leaves a large floor much darker than its stated colour; a little
    // self-illumination keeps it reading as the light surface it is meant to be.
    const groundColor = new THREE.Color(spec.color || '#dddddd');
    const plane = new THREE.Mesh(
      new THREE.PlaneBufferGeometry(size, size),
      new THREE.MeshStandardMaterial({ color: groundColor, emissive: groundColor.clone().multiplyScalar(0.25), roughness: 1 })
    );
    plane.rotation.x = -Math.PI / 2; // the plane geometry lies in xy; the ground is horizontal
    group.add(plane);
    // About 20 cells with a round cell size (0.1, 0.2, 0.5, 1 ...) so distances can be read.
    const cell = niceStep(size / 20);
    const divisions = Math.max(1, Math.round(size / cell));
    const grid = new THREE.GridHelper(size, divisions, 0x8a939b, 0xb4bbc1);
    grid.position.y = 1e-3 * size; // lifted off the plane to avoid z-fighting
    group.add(grid);
    group.position.y = spec.y || 0;
    return { object3d: group, box: null, showFrame() {}, setWireframe() {} };
  }

  function niceStep(raw) {
    const power = Math.pow(10, Math.floor(Math.log10(raw)));
    const mantissa = raw / power;
    return (mantissa < 1.5 ? 1 : mantissa < 3.5 ? 2 : mantissa < 7.5 ? 5 : 10) * power;
  }

  function makeSceneObject(spec, data) {
    switch (spec.type) {
      case 'mesh': return makeMesh(spec, data);
      case 'points': return makePoints(spec, data);
      case 'sphere': return makeSphere(spec);
      case 'ground': return makeGround(spec);
      default: throw new Error('unknown object type "' + spec.type + '"');
    }
  }

  // ---- Panes: one canvas, renderer, camera and OrbitControls each ----

  function unionBox(boxes) {
    const box = new THREE.Box3();
    for (const b of boxes) {
      if (b) box.union(new THREE.Box3(new THREE.Vector3(b[0], b[1], b[2]), new THREE.Vector3(b[3], b[4], b[5])));
    }
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, 0, -1), new THREE.Vector3(1, 1, 1));
    return box;
  }

  // A view from the front, a little to the side and above, as one looks at a table top.
  function defaultViewDirection(up) {
    const u = new THREE.Vector3().fromArray(up).normalize();
    const side = Math.abs(u.z) < 0.9 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(0, -1, 0);
    const front = side.sub(u.clone().multiplyScalar(side.dot(u))).normalize();
    const right = new THREE.Vector3().crossVectors(u, front).normalize();
    return front.add(right.multiplyScalar(-0.45)).add(u.multiplyScalar(0.55)).normalize();
  }

  function createPane(paneSpec, paneData, header, index) {
    const root = el('section', 'kit-pane');
    const view = el('div', 'kit-view');
    const ended = el('div', 'kit-ended', paneSpec.ended || 'run ended');
    ended.hidden = true;
    append(root, view);

    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    // The scene's own background when it has one (chapter 5's sprites glow on a dark sky).
    renderer.setClearColor(header.background ? new THREE.Color(header.background) : 0xfafbfc, 1);
    view.appendChild(renderer.domElement);
    view.appendChild(ended);

    const scene = new THREE.Scene();
    const objects = paneSpec.objects.map((spec, i) => makeSceneObject(spec, paneData[i]));
    objects.forEach((o) => scene.add(o.object3d));
    addLights(scene, header.up);
    paneSpec.objects.forEach((spec) => { if (spec.scalar) view.appendChild(makeLegend(spec.scalar)); });

    const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
    camera.up.fromArray(header.up);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.enableDamping = false; // damping needs a running loop; we render on demand
    const frameBox = unionBox(objects.map((o) => o.box));

    const pane = {
      spec: paneSpec, root, view, ended, renderer, scene, camera, controls, objects, frameBox,
      info: createPaneInfo(paneSpec, index),
      shownFrame: -1,
    };
    root.appendChild(pane.info.root);
    return pane;
  }

  function addLights(scene, up) {
    const u = new THREE.Vector3().fromArray(up).normalize();
    const hemisphere = new THREE.HemisphereLight(0xffffff, 0xa8a49e, 0.7);
    hemisphere.position.copy(u);
    scene.add(hemisphere);
    const sun = new THREE.DirectionalLight(0xffffff, 0.5);
    sun.position.copy(defaultViewDirection(up)).add(u.clone().multiplyScalar(1.5)).normalize();
    scene.add(sun);
  }

  function makeLegend(scalar) {
    const legend = el('div', 'kit-legend');
    const unit = scalar.unit ? ' [' + scalar.unit + ']' : '';
    const bar = el('div', 'kit-legend-bar');
    bar.style.background = colormapCss();
    const ends = el('div', 'kit-legend-ends');
    append(ends, el('span', '', formatNumber(scalar.min, 3)), el('span', '', formatNumber(scalar.max, 3)));
    return append(legend, el('div', '', scalar.name + unit), bar, ends);
  }

  // Label, cost, the pane's own clock, readouts and static facts, under the view.
  function createPaneInfo(paneSpec, index) {
    const root = el('div', 'kit-info');
    const title = root.appendChild(el('div', 'kit-info-title'));
    title.appendChild(el('div', 'kit-label', paneSpec.label || 'pane ' + (index + 1)));
    if (paneSpec.cost) title.appendChild(el('div', 'kit-cost', paneSpec.cost));
    const clock = title.appendChild(el('div', 'kit-paneclock'));
    const list = root.appendChild(el('dl'));
    const readouts = (paneSpec.readouts || []).map((readout) => {
      const raw = el('output', 'kit-readout kit-raw');
      raw.dataset.pane = String(index);
      raw.dataset.name = readout.name;
      const shown = el('span');
      append(list, el('dt', '', readout.name), append(el('dd'), shown, raw));
      return { spec: readout, raw, shown };
    });
    for (const [name, value] of paneSpec.facts || []) append(list, el('dt', '', name), el('dd', '', value));
    return { root, clock, readouts };
  }

  // Points the camera at the pane's objects and moves it back just far enough that every
  // corner of their box is inside the view, with a small margin, whatever the aspect.
  function frameCamera(pane, up) {
    const { camera, controls, frameBox } = pane;
    const center = frameBox.getCenter(new THREE.Vector3());
    const back = defaultViewDirection(up);
    const right = new THREE.Vector3().crossVectors(new THREE.Vector3().fromArray(up), back).normalize();
    const upward = new THREE.Vector3().crossVectors(back, right);
    const tanV = Math.tan((camera.fov * Math.PI) / 360);
    const tanH = tanV * camera.aspect;
    let distance = 1e-3;
    for (const corner of boxCorners(frameBox)) {
      const offset = corner.sub(center);
      const depth = offset.dot(back); // towards the camera
      distance = Math.max(distance,
        depth + Math.abs(offset.dot(right)) / tanH,
        depth + Math.abs(offset.dot(upward)) / tanV);
    }
    distance *= 1.1;
    camera.position.copy(center).add(back.multiplyScalar(distance));
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
  }

  function boxCorners(box) {
    const corners = [];
    for (const x of [box.min.x, box.max.x]) {
      for (const y of [box.min.y, box.max.y]) {
        for (const z of [box.min.z, box.max.z]) corners.push(new THREE.Vector3(x, y, z));
      }
    }
    return corners;
  }

  function resizePane(pane) {
    const width = Math.max(1, pane.view.clientWidth);
    const height = Math.max(1, pane.view.clientHeight);
    pane.renderer.setSize(width, height, false); // CSS sizes the canvas; this sets its buffer
    pane.camera.aspect = width / height;
    pane.camera.updateProjectionMatrix();
    // Pixels per metre at unit distance, for the world-sized particle sprites.
    const pixelsPerUnit = (height * pane.renderer.getPixelRatio()) / (2 * Math.tan((pane.camera.fov * Math.PI) / 360));
    pane.objects.forEach((o) => { if (o.setPixelsPerUnit) o.setPixelsPerUnit(pixelsPerUnit); });
  }

  // ---- Formatting ----

  // Significant digits, without exponent notation for ordinary magnitudes.
  function formatNumber(value, digits) {
    if (value === null || value === undefined) return 'n/a';
    if (!isFinite(value)) return String(value); // NaN or Infinity: a diverged run, say so plainly
    if (Number.isInteger(value) && Math.abs(value) < 1e9) return String(value); // counts
    const magnitude = Math.abs(value);
    if (magnitude !== 0 && (magnitude >= 1e9 || magnitude < 1e-4)) return value.toExponential(digits - 1);
    if (magnitude >= Math.pow(10, digits)) return value.toFixed(0);
    return value.toPrecision(digits); // keeps trailing zeros: digits are meant to line up
  }

  function formatTime(t) { return 't = ' + t.toFixed(3) + ' s'; }

  // ---- The player: shared clock, controls bar and per-frame updates ----

  function createControls(player) {
    const bar = el('div', 'kit-controls');
    const play = el('button', 'kit-play', '\u25B6 Play');
    play.type = 'button';
    play.title = 'play / pause (space)';
    const slider = el('input', 'kit-slider');
    Object.assign(slider, { type: 'range', min: 0, max: player.frameCount - 1, step: 1, value: 0 });
    slider.setAttribute('aria-label', 'frame');

    const clock = el('span', 'kit-clock');
    const frameOut = el('output');
    frameOut.id = 'kit-frame';
    const timeOut = el('output', 'kit-raw');
    timeOut.id = 'kit-time';
    const timeShown = el('span');
    append(clock, document.createTextNode('frame '), frameOut,
      document.createTextNode(' / ' + (player.frameCount - 1) + ' \u00B7 '), timeShown, timeOut);

    const speed = el('select');
    speed.setAttribute('aria-label', 'playback speed');
    for (const s of SPEEDS) {
      const option = el('option', '', s + '\u00D7');
      option.value = String(s);
      option.selected = s === 1;
      speed.appendChild(option);
    }
    const loop = el('input');
    loop.type = 'checkbox';
    loop.checked = true;
    const wire = el('button', '', 'wireframe');
    wire.type = 'button';
    wire.title = 'switch between shaded surfaces and wireframe';
    const reset = el('button', '', 'reset view');
    reset.type = 'button';

    append(bar, play, slider, clock,
      append(el('label', '', 'speed '), speed),
      append(el('label'), loop, document.createTextNode('loop')),
      wire, reset);

    play.addEventListener('click', () => player.togglePlay());
    slider.addEventListener('input', () => { player.pause(); player.showFrame(Number(slider.value)); });
    speed.addEventListener('change', () => player.setSpeed(Number(speed.value)));
    loop.addEventListener('change', () => { player.loop = loop.checked; });
    wire.addEventListener('click', () => {
      player.setWireframe(!player.wireframe);
      wire.textContent = player.wireframe ? 'shaded' : 'wireframe';
    });
    reset.addEventListener('click', () => player.resetViews());
    return { bar, play, slider, frameOut, timeOut, timeShown };
  }

  function createPlayer(header, decoded) {
    const player = {
      header,
      frameCount: header.times.length,
      frame: 0,
      playing: false,
      speed: 1,
      loop: true,
      wireframe: false,
      panes: [],
    };

    append(document.body, buildHeading(header));
    player.ui = createControls(player);
    document.body.appendChild(player.ui.bar);
    const panesRoot = el('main', 'kit-panes');
    document.body.appendChild(panesRoot);
    player.panes = header.panes.map((spec, i) => createPane(spec, decoded[i], header, i));
    player.panes.forEach((pane) => panesRoot.appendChild(pane.root));
    if (header.precision) document.body.appendChild(el('footer', 'kit-footer', header.precision));

    player.panes.forEach((pane) => {
      resizePane(pane);
      frameCamera(pane, header.up);
      // Orbiting only moves the camera: redraw that pane, the clock stays put.
      pane.controls.addEventListener('change', () => requestPaneRender(pane));
    });

    Object.assign(player, {
      showFrame: (k) => showFrame(player, k),
      togglePlay: () => (player.playing ? player.pause() : player.play()),
      play: () => startPlaying(player),
      pause: () => stopPlaying(player),
      setSpeed(s) {
        // Restart the playback clock so that the change of rate does not jump frames.
        const wasPlaying = player.playing;
        if (wasPlaying) stopPlaying(player);
        player.speed = s;
        if (wasPlaying) startPlaying(player);
      },
      setWireframe(on) {
        player.wireframe = on;
        player.panes.forEach((pane) => pane.objects.forEach((o) => o.setWireframe(on)));
        renderAll(player);
      },
      resetViews() {
        player.panes.forEach((pane) => { frameCamera(pane, header.up); renderPane(pane); });
      },
    });
    return player;
  }

  function buildHeading(header) {
    const heading = el('header', 'kit-header');
    heading.appendChild(el('h1', '', header.title || 'Simulation'));
    if (header.subtitle) heading.appendChild(el('p', 'kit-subtitle', header.subtitle));
    if (header.title) document.title = header.title;
    return heading;
  }

  const pendingRenders = new Set();
  function requestPaneRender(pane) {
    if (pendingRenders.size === 0) {
      requestAnimationFrame(() => {
        pendingRenders.forEach(renderPane);
        pendingRenders.clear();
      });
    }
    pendingRenders.add(pane);
  }

  function renderPane(pane) { pane.renderer.render(pane.scene, pane.camera); }

  function renderAll(player) { player.panes.forEach(renderPane); }

  // Moves every pane to page frame k, updates all text, draws, then tells tests it is done.
  function showFrame(player, k) {
    k = Math.max(0, Math.min(player.frameCount - 1, Math.round(k)));
    player.frame = k;
    const ui = player.ui;
    ui.slider.value = String(k);
    ui.frameOut.textContent = String(k);
    ui.timeOut.textContent = String(player.header.times[k]);
    ui.timeShown.textContent = formatTime(player.header.times[k]);
    player.panes.forEach((pane) => showPaneFrame(pane, k, player.header.times));
    renderAll(player);
    // Where each pane's canvas lies on the page [CSS px], so that a test of the screenshot looks
    // inside the 3D view and not at the text around it.
    player.panes.forEach((pane) => {
      const r = pane.renderer.domElement.getBoundingClientRect();
      pane.renderer.domElement.dataset.kitRect = [r.left, r.top, r.width, r.height].map(Math.round).join(',');
    });
    document.body.dataset.kitReady = String(k);
  }

  function showPaneFrame(pane, k, times) {
    const frames = pane.spec.frames;
    const f = Math.min(k, frames - 1);
    pane.ended.hidden = !(pane.spec.ended && k >= frames);
    if (pane.shownFrame !== f) {
      pane.objects.forEach((o) => o.showFrame(f));
      pane.shownFrame = f;
    }
    pane.info.clock.textContent = formatTime(times[f]) + ' \u00B7 frame ' + f + ' / ' + (frames - 1);
    for (const r of pane.info.readouts) {
      const value = r.spec.values[f];
      r.raw.textContent = value === null || value === undefined ? '' : String(value);
      const unit = r.spec.unit && value !== null && value !== undefined ? ' ' + r.spec.unit : '';
      r.shown.textContent = formatNumber(value, r.spec.digits || 4) + unit;
    }
  }

  // Playback follows the wall clock (fps * speed page frames per second) rather than
  // counting animation callbacks, so slow machines skip frames instead of slowing down.
  function startPlaying(player) {
    if (player.frame >= player.frameCount - 1) showFrame(player, 0);
    player.playing = true;
    player.ui.play.textContent = '\u275A\u275A Pause';
    const startFrame = player.frame;
    const startTime = performance.now();
    const rate = (player.header.fps || 30) * player.speed;
    const tick = (now) => {
      if (!player.playing) return;
      let k = startFrame + Math.floor(((now - startTime) / 1000) * rate);
      if (k >= player.frameCount) {
        if (!player.loop) { showFrame(player, player.frameCount - 1); stopPlaying(player); return; }
        k %= player.frameCount;
      }
      if (k !== player.frame) showFrame(player, k);
      player.animation = requestAnimationFrame(tick);
    };
    player.animation = requestAnimationFrame(tick);
  }

  function stopPlaying(player) {
    player.playing = false;
    cancelAnimationFrame(player.animation);
    player.ui.play.textContent = '\u25B6 Play';
  }

  // "#frame=K" opens paused at K (clamped), "#frame=last" at the end; otherwise frame 0.
  function frameFromHash(frameCount) {
    const match = /(?:^#|&)frame=([^&]*)/.exec(window.location.hash);
    if (!match) return 0;
    if (match[1] === 'last') return frameCount - 1;
    const k = parseInt(match[1], 10);
    return isNaN(k) ? 0 : Math.max(0, Math.min(frameCount - 1, k));
  }

  function bindKeys(player) {
    document.addEventListener('keydown', (event) => {
      if (event.target.tagName === 'INPUT' || event.target.tagName === 'SELECT') return;
      if (event.key === ' ') { event.preventDefault(); player.togglePlay(); }
      else if (event.key === 'ArrowRight') { player.pause(); player.showFrame(player.frame + 1); }
      else if (event.key === 'ArrowLeft') { player.pause(); player.showFrame(player.frame - 1); }
    });
  }

  function webglAvailable() {
    try {
      const canvas = document.createElement('canvas');
      return !!(window.WebGLRenderingContext && (canvas.getContext('webgl') || canvas.getContext('experimental-webgl')));
    } catch (e) {
      return false;
    }
  }

  function validateHeader(header) {
    if (header.format !== 1) throw new Error('unsupported format ' + header.format);
    if (!Array.isArray(header.times) || header.times.length === 0) throw new Error('no frames');
    if (!Array.isArray(header.panes) || header.panes.length < 1 || header.panes.length > 4) {
      throw new Error('expected 1 to 4 panes');
    }
    header.up = header.up || [0, 1, 0];
  }

  async function main() {
    const script = document.getElementById('kit-data');
    if (!script) throw new Error('no kit-data header in the page');
    const header = JSON.parse(script.textContent);
    validateHeader(header);
    if (header.title) document.title = header.title;
    if (typeof THREE === 'undefined' || !THREE.OrbitControls) throw new Error('three.js is missing');
    if (!webglAvailable()) {
      document.body.appendChild(buildHeading(header));
      fail('no WebGL', 'This page needs WebGL to draw the simulation, and this browser could not ' +
        'create a WebGL context (3D graphics may be switched off or unsupported here).');
      return;
    }
    // Decode every pane's blobs in parallel before building anything, so the first
    // frame shown is complete.
    const decoded = await Promise.all(header.panes.map((pane) => Promise.all(pane.objects.map(decodeObject))));
    const player = createPlayer(header, decoded);
    bindKeys(player);
    window.addEventListener('resize', () => {
      player.panes.forEach(resizePane);
      renderAll(player);
    });
    window.addEventListener('hashchange', () => { player.pause(); player.showFrame(frameFromHash(player.frameCount)); });
    showFrame(player, frameFromHash(player.frameCount));
  }

  main().catch((error) => fail(error && error.message ? error.message : String(error)));
})();
