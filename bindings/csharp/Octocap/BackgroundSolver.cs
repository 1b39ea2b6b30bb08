using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using System.Threading;

namespace Octocap
{
    /// <summary>Solves frames from pixels on a worker thread, for game loops that capture on their own thread (Unity's
    /// WebCamTexture can only be read there): the caller rents an image set, fills it and submits it, never waiting;
    /// the worker detects and solves the newest set submitted (one waits at most: a newer one replaces it, counted)
    /// and hands each solved frame over through <see cref="IFrameSource"/>. The session is the worker's while this
    /// solver lives: do not call it from elsewhere.</summary>
    public sealed class BackgroundSolver : IFrameSource, IDisposable
    {
        /// <summary>One picture per camera (calibration order), top-down rows, <see cref="Format"/> pixels.</summary>
        public sealed class ImageSet
        {
            public byte[][] Pixels;
            public int[] Width, Height;
            public PixelFormat Format = PixelFormat.Rgba8;
            public long TimestampUs;

            internal ImageSet(int views)
            {
                Pixels = new byte[views][];
                Width = new int[views];
                Height = new int[views];
            }

            /// <summary>Makes view <paramref name="v"/> hold a w x h picture (4 bytes a pixel) and returns its buffer.</summary>
            public byte[] Resize(int v, int w, int h)
            {
                if (w <= 0 || h <= 0) throw new ArgumentOutOfRangeException(nameof(w), "a picture of " + w + "x" + h);
                if (Pixels[v] == null || Pixels[v].Length != w * h * 4) Pixels[v] = new byte[w * h * 4];
                Width[v] = w;
                Height[v] = h;
                return Pixels[v];
            }
        }

        readonly Session _session;
        readonly int _views;
        readonly object _lock = new object();
        readonly Stack<ImageSet> _free = new Stack<ImageSet>();
        readonly Thread _thread;
        ImageSet _pending;
        Frame _latest;
        bool _stop;
        long _solved, _replaced;
        string _lastError;

        public BackgroundSolver(Session session, int views)
        {
            if (session == null) throw new ArgumentNullException(nameof(session));
            if (views <= 0) throw new ArgumentOutOfRangeException(nameof(views));
            _session = session;
            _views = views;
            _thread = new Thread(Run) { IsBackground = true, Name = "octocap solver" };
            _thread.Start();
        }

        /// <summary>Sets solved so far.</summary>
        public long Solved { get { lock (_lock) return _solved; } }
        /// <summary>Sets replaced by a newer one before the worker took them (the worker was busy).</summary>
        public long Replaced { get { lock (_lock) return _replaced; } }
        /// <summary>Why the last set could not be solved (null when it was).</summary>
        public string LastError { get { lock (_lock) return _lastError; } }

        /// <summary>A set to fill: a free one, else the one waiting (it will not be solved: counted as replaced).</summary>
        public ImageSet Rent()
        {
            lock (_lock)
            {
                if (_stop) throw new ObjectDisposedException(nameof(BackgroundSolver));
                if (_free.Count > 0) return _free.Pop();
                if (_pending != null)
                {
                    ImageSet taken = _pending;
                    _pending = null;
                    ++_replaced;
                    return taken;
                }
                return new ImageSet(_views);  // at most three exist: filling, waiting, being solved
            }
        }

        /// <summary>Hands a filled set to the worker; returns at once. A set still waiting is replaced.</summary>
        public void Submit(ImageSet set)
        {
            if (set == null || set.Pixels.Length != _views) throw new ArgumentException("a set of this solver's views", nameof(set));
            lock (_lock)
            {
                if (_stop) throw new ObjectDisposedException(nameof(BackgroundSolver));
                if (_pending != null)
                {
                    _free.Push(_pending);
                    ++_replaced;
                }
                _pending = set;
                Monitor.Pulse(_lock);
            }
        }

        /// <summary>The newest frame solved since the last call, or null. The caller disposes it.</summary>
        public Frame TryGetFrame()
        {
            lock (_lock)
            {
                Frame f = _latest;
                _latest = null;
                return f;
            }
        }

        void Run()
        {
            var images = new Image[_views];
            var pins = new GCHandle[_views];
            for (;;)
            {
                ImageSet set;
                lock (_lock)
                {
                    while (_pending == null && !_stop) Monitor.Wait(_lock);
                    if (_stop) return;
                    set = _pending;
                    _pending = null;
                }
                Frame frame = null;
                string error = null;
                try
                {
                    for (int v = 0; v < _views; ++v)
                    {
                        pins[v] = GCHandle.Alloc(set.Pixels[v], GCHandleType.Pinned);
                        images[v] = new Image { Pixels = pins[v].AddrOfPinnedObject(), Width = (uint)set.Width[v],
                                                Height = (uint)set.Height[v], StrideBytes = (uint)(set.Width[v] * 4),
                                                Format = set.Format };
                    }
                    _session.SolveImages(images, set.TimestampUs);  // Ok or NoPerson; errors throw
                    frame = _session.TryGetFrame();
                }
                catch (Exception e)
                {
                    error = e.Message;
                }
                finally
                {
                    for (int v = 0; v < _views; ++v)
                        if (pins[v].IsAllocated) pins[v].Free();
                }
                lock (_lock)
                {
                    _lastError = error;
                    if (frame != null)
                    {
                        _latest?.Dispose();
                        _latest = frame;
                        ++_solved;
                    }
                    _free.Push(set);
                }
            }
        }

        /// <summary>Stops the worker (after the set it is solving) and releases the frame not taken.</summary>
        public void Dispose()
        {
            lock (_lock)
            {
                if (_stop) return;
                _stop = true;
                Monitor.PulseAll(_lock);
            }
            _thread.Join();
            lock (_lock)
            {
                _latest?.Dispose();
                _latest = null;
            }
        }
    }
}
