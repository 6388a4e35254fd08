"""Running kiln on an exported scene and following its progress. No bpy: usable in tests.

kiln is started as ``kiln SCENE -o IMAGE.exr --spp N --seed S [--threads T]
[--emission M] --write-partial-images --quiet``. With --write-partial-images kiln rewrites the
EXR (atomically, by renaming a finished file over it) after every wave of samples (1, 2, 4,
... samples per pixel), recording the samples per pixel it holds in ``samplesPerPixel``.
``stop()`` sends SIGINT: kiln then writes the image so far and exits with status 130.
"""

import os
import signal
import subprocess
import threading
import time

from . import exr_header


def kiln_command(executable, scene_path, image_path, samples, seed=0, threads=0, emission=None):
    """The kiln command line (a list) rendering ``scene_path`` to ``image_path``."""
    command = [executable, scene_path, "-o", image_path, "--spp", str(int(samples)),
               "--seed", str(int(seed))]
    if threads > 0:
        command += ["--threads", str(int(threads))]
    if emission:
        command += ["--emission", emission]
    command += ["--write-partial-images", "--quiet"]
    return command


class KilnRun:
    """One kiln process. ``poll()`` returns (new image?, samples per pixel in it) and
    ``returncode`` is set once it has exited; ``stderr_text()`` is what kiln printed on
    standard error (standard output is kept too, in ``stdout_text()``)."""

    def __init__(self, command, cwd=None):
        self.command = command
        self.image_path = command[command.index("-o") + 1]
        self._seen = None
        self._stderr = []
        self._stdout = []
        self.process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
        self._threads = [threading.Thread(target=self._drain, args=(self.process.stderr,
                                                                    self._stderr), daemon=True),
                         threading.Thread(target=self._drain, args=(self.process.stdout,
                                                                    self._stdout), daemon=True)]
        for thread in self._threads:
            thread.start()

    @staticmethod
    def _drain(stream, sink):
        for line in iter(stream.readline, b""):
            sink.append(line.decode("utf-8", "replace"))
        stream.close()

    @property
    def returncode(self):
        return self.process.poll()

    def poll(self):
        """(True, spp) if the image file changed since the last call (spp: the samples per
        pixel it holds, or None if unreadable), else (False, None)."""
        try:
            stat = os.stat(self.image_path)
        except OSError:
            return False, None
        signature = (stat.st_mtime_ns, stat.st_size, stat.st_ino)
        if signature == self._seen:
            return False, None
        self._seen = signature
        try:
            return True, exr_header.samples_per_pixel(self.image_path)
        except (OSError, ValueError):
            return True, None

    def stop(self):
        """Ask kiln to stop (SIGINT): it writes the image so far and exits (status 130)."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)

    def wait(self, timeout=None):
        """Wait for kiln to exit (kill it if ``timeout`` seconds pass); its exit status."""
        try:
            self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        for thread in self._threads:
            thread.join(1.0)
        return self.process.returncode

    def stderr_text(self):
        return "".join(self._stderr)

    def stdout_text(self):
        return "".join(self._stdout)


def sleep_briefly(seconds=0.1):
    """Pause between polls."""
    time.sleep(seconds)
