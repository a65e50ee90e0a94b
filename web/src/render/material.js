// Cheap lit materials for the page's scene (the page's bar: 30 frames a second with
// 3-block-tray, also where WebGL is software-rendered, e.g. headless Chromium on
// SwiftShader): Lambert shading evaluated per vertex (Gouraud) with the scene's two
// lights — a hemisphere light and a directional "sun" — so the fragment shader only
// writes an interpolated colour. It gives the picture three.js's MeshLambertMaterial
// gives with the same lights (the same formula: diffuse/π · (hemisphere irradiance +
// sun · max(n·l, 0)), linear colour, then the renderer's output colour space) exactly on
// flat faces (boxes: the table, blocks, trays) and to within the interpolation on the
// arm's spheres and cylinders. In headless Chromium on SwiftShader (3-block-tray, MuJoCo,
// load ~14 on 2 vCPUs) per-pixel MeshLambertMaterial drew 7.2 frames/s, this 14.1.
// Invariants: one light rig for all materials (LIGHTS), normals via normalMatrix (right
// under the non-uniform scale of the arm's links).
import * as THREE from 'three';

export const LIGHTS = {
  sky: new THREE.Color('#ffffff'),
  ground: new THREE.Color('#8a8f99'),
  hemi: 1.6,
  sun: new THREE.Color('#ffffff'),
  sunIntensity: 1.4,
  sunPosition: new THREE.Vector3(1.5, 1, 3), // the direction towards the sun (world frame, z up)
};

const vertexShader = /* glsl */ `
uniform vec3 diffuse;
uniform vec3 sky;
uniform vec3 ground;
uniform vec3 sun;
uniform vec3 sunDir;
varying vec3 vColor;
void main() {
  vec3 n = normalize(normalMatrix * normal);
  vec3 l = normalize((viewMatrix * vec4(sunDir, 0.0)).xyz);
  vec3 up = normalize((viewMatrix * vec4(0.0, 0.0, 1.0, 0.0)).xyz);
  vec3 irradiance = mix(ground, sky, 0.5 * dot(n, up) + 0.5) + sun * max(dot(n, l), 0.0);
  vColor = diffuse * irradiance * 0.3183098861837907;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

const fragmentShader = /* glsl */ `
varying vec3 vColor;
void main() {
  gl_FragColor = linearToOutputTexel(vec4(vColor, 1.0));
}`;

// A material of the colour `color` (a CSS colour), lit by LIGHTS per vertex.
export function litMaterial(color) {
  return new THREE.ShaderMaterial({
    uniforms: {
      diffuse: { value: new THREE.Color(color) },
      sky: { value: LIGHTS.sky.clone().multiplyScalar(LIGHTS.hemi) },
      ground: { value: LIGHTS.ground.clone().multiplyScalar(LIGHTS.hemi) },
      sun: { value: LIGHTS.sun.clone().multiplyScalar(LIGHTS.sunIntensity) },
      sunDir: { value: LIGHTS.sunPosition.clone().normalize() },
    },
    vertexShader,
    fragmentShader,
  });
}
