//! The examples at the end of each command's `--help` (clap's `after_help`):
//! command lines that a newcomer can copy, each with what it does. A test in
//! `main.rs` parses every one of them.

pub const PATHTRACER: &str = "\
Examples:
  pathtracer render testcases/smallpt.txt
      render into output/smallpt.bmp, linear 8-bit as the course framework wrote it
  pathtracer render my_scene.txt --gamma 2.2 -o output/my_scene.png
      an image to look at on a screen
  pathtracer check my_scene.txt
      read a scene file, report its mistakes with line and column, render nothing
  pathtracer view my_scene.txt
      watch the picture converge in a browser
  pathtracer compare output/ours.bmp my_render.png
      how far apart two images are, in numbers and to the eye
  pathtracer help render
      every option of one command

The user guide is docs/guide/README.md; every option is in docs/guide/options.md.";

pub const CHECK: &str = "\
Examples:
  pathtracer check my_scene.txt
      the dialect, look, objects and warnings of one file
  pathtracer check testcases/tutorial1_camera.txt testcases/tutorial2_sphere.txt
      several files, one summary each
  pathtracer check my_scene.txt --strict
      fail on warnings too (unknown fields, count mismatches)";

pub const RENDER: &str = "\
Examples:
  pathtracer render my_scene.txt
      output/my_scene.bmp at 40 spp: linear 8-bit, to compare with coursework images
  pathtracer render my_scene.txt --gamma 2.2 -o output/my_scene.png
      display-encoded, to look at
  pathtracer render my_scene.txt --width 320 --height 240 --spp 16
      a quick, smaller preview
  pathtracer render my_scene.txt --spp 4096 -o output/my_scene.pfm
      linear floating point; Ctrl-C stops it and writes what it has
  pathtracer render my_scene.txt --spp 4096 -o output/my_scene.pfm --resume
      continue that render from its checkpoint
  pathtracer render my_scene.txt --time-budget 60
      as many samples as fit in a minute
  pathtracer render my_scene.txt --look physical
      with this project's physically based conventions instead of the file's renderer's
  pathtracer render my_scene.txt --debug-sample 120,80,0
      print the path of sample 0 of pixel (120, 80), every vertex and term, no image";

pub const MERGE: &str = "\
Examples:
  pathtracer render my_scene.txt --film output/a.exr --samples 0..32
  pathtracer render my_scene.txt --film output/b.exr --samples 32..64
  pathtracer merge output/a.exr output/b.exr -o output/my_scene.png --gamma 2.2
      two render jobs of 32 spp each, merged into the image of one 64-spp render";

pub const COMPARE: &str = "\
Examples:
  pathtracer compare output/ours.bmp my_render.png
      RMSE, relative MSE, PSNR, SSIM, FLIP and whether they look alike
  pathtracer compare output/ours.bmp my_render.png --diff output/diff.png
      and where they differ, as a heat map
  pathtracer compare output/ours.pfm output/reference.pfm --json
      the same figures as JSON, for scripts";

pub const LOOKALIKE: &str = "\
Examples:
  pathtracer lookalike ../shared/reference/pairs.tsv
      every sure pair at 160 px wide and 64 spp, into output/lookalike/index.html
  pathtracer lookalike ../shared/reference/pairs.tsv --folder yuzc19 --look physical
      one folder's pairs in another look";

pub const CONVERT: &str = "\
Examples:
  pathtracer convert output/my_scene.pfm output/my_scene.png --gamma 2.2
      a display-encoded picture of a linear render
  pathtracer convert output/my_scene.pfm output/my_scene.bmp --tonemap reinhard --gamma 2.2
      bright lights compressed instead of clipped";

pub const CONVERGE: &str = "\
Examples:
  pathtracer converge my_scene.txt --max-spp 256
      renders a 4096-spp reference into output/my_scene_reference.pfm first, then
      1, 2, 4, ... 256 spp into output/my_scene_converge.csv and .svg
  pathtracer render my_scene.txt --width 256 --height 192 --spp 4096 -o output/ref.pfm
  pathtracer converge my_scene.txt --width 256 --height 192 --reference output/ref.pfm
      smaller, against a reference rendered once (the same size)";

pub const PLOT: &str = "\
Examples:
  pathtracer plot path=output/a_converge.csv original=output/b_converge.csv -o output/curves.svg
      two error-against-time curves on one log-log plot
  pathtracer plot output/a_converge.csv -o output/a.svg --column ssim --title \"SSIM of a\"
      another column, with a title";

pub const COMPLETIONS: &str = "\
Examples:
  pathtracer completions bash > ~/.local/share/bash-completion/completions/pathtracer
  pathtracer completions zsh > ~/.zfunc/_pathtracer
      (with `fpath+=~/.zfunc` before `compinit` in ~/.zshrc)
  pathtracer completions fish > ~/.config/fish/completions/pathtracer.fish";

pub const VIEW: &str = "\
Examples:
  pathtracer view my_scene.txt
      prints a URL on 127.0.0.1: open it to watch the picture sharpen
  pathtracer view my_scene.txt --width 320 --height 240 --port 8080
      smaller, at http://127.0.0.1:8080/";
