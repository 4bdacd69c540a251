// The 3D view of a registered pair: both clouds in the target's canonical frame (three.js points, orbit).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

let view = null;

function points(flat, color) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.Float32BufferAttribute(flat, 3));
  return new THREE.Points(geometry, new THREE.PointsMaterial({ color, size: 1.5, sizeAttenuation: false }));
}

export function threeView(container, clouds) {
  if (!view) {
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setSize(container.clientWidth || 360, container.clientHeight || 360);
    container.appendChild(renderer.domElement);
    const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1000);
    camera.position.set(0, -30, 30);
    camera.up.set(0, 0, 1);
    const controls = new OrbitControls(camera, renderer.domElement);
    view = { renderer, camera, controls, scene: null };
    const loop = () => {
      controls.update();
      if (view.scene && container.offsetParent !== null) renderer.render(view.scene, camera); // only when shown
      requestAnimationFrame(loop);
    };
    loop();
  }
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x111111);
  scene.add(points(clouds.target, 0xd4a060));
  scene.add(points(clouds.source, 0x4f9be8));
  const box = new THREE.Box3().setFromObject(scene);
  const radius = box.getSize(new THREE.Vector3()).length() / 2 || 10;
  view.camera.position.set(0, -1.4 * radius, 1.4 * radius);
  view.controls.target.set(0, 0, 0);
  view.scene = scene;
}
