// A clock for X_ITE that only moves when the test moves it, so that a scene with running TimeSensors
// renders the same picture at the same scene time, every run.
//
// X_ITE 15 reads its time from Date.now() alone (X3DTimeContext.advanceTime, TimeSensor, pause and
// resume); performance.now() and requestAnimationFrame drive nothing of the scene's state. The init
// script replaces Date.now() by a value that stays at `kClockOrigin` seconds from the page's start,
// through the whole load, until window.cadnurbsClock.set(seconds) moves it.
//
// X_ITE skips a frame (no events, no drawing) unless its clock advanced by more than
// 1 / MaximumFrameRate since the last frame, and the load itself needs frames (its events are
// processed in them). cadnurbsClock.attach(browser), before loadURL, makes every frame run at the
// clock's current value, advanced or not, and sets MaximumFrameRate to 1e6 so that 1 ms steps count.
// With the clock frozen through the load, a looping TimeSensor with startTime 0 starts, pauses while
// its scene is not live and resumes at the same instant, so its fraction at clock time T is
// fract(T / cycleInterval), whatever the load took (on the real clock the load's duration shifts it).
//
// setClockAndDraw() draws `frames` frames at T - (frames - 1) ms ... T, so the last frame is exactly at
// T and the ones before let events through PROTO Scripts settle. Times must grow from one call to the
// next (equal times draw more frames at the same instant).
//
// hold(), once the load is done, stops the frames nobody asked for: X_ITE keeps drawing frames on
// requestAnimationFrame while events are pending, and a scene whose ROUTEs form a loop (robot_opengl's
// ProximitySensor moving its own parent Transform) has events pending in every frame, so without it the
// number of frames between two pictures, and the loop's state in the picture, would follow the wall
// clock. Held, the loop's state is a function of the frames drawn during the load and the frames asked for.

// An instant (s since the epoch) at which every cycle of the corpus files starts: 1,700,001,870 =
// 3570 x 476191 is a multiple of 10, 3, 2, 1, 0.85 and 0.56 s. Scene time t is kClockOrigin + t.
export const kClockOrigin = 1700001870;

// For XiteSession's initScript.
export const virtualClockInitScript = {
  script: (originSeconds) => {
    let nowMs = originSeconds * 1000;
    Date.now = () => nowMs;
    window.cadnurbsClock = {
      set: (seconds) => {
        nowMs = seconds * 1000;
      },
      // Frames the test asked for and X_ITE has not drawn yet; null: every frame is drawn (the load).
      framesAllowed: null,
      attach: (browser) => {
        browser.setBrowserOption('MaximumFrameRate', 1e6);
        const advanceTime = browser.advanceTime;
        const clock = window.cadnurbsClock;
        browser.advanceTime = function() {
          advanceTime.call(this);
          if (clock.framesAllowed === null) return true;
          if (clock.framesAllowed === 0) return false;
          --clock.framesAllowed;
          return true;
        };
      },
      // After the load: from now on X_ITE draws only the frames setClockAndDraw asks for.
      hold: () => {
        window.cadnurbsClock.framesAllowed = 0;
      },
    };
  },
  arg: kClockOrigin,
};

// In the page: draws `frames` frames ending at scene time t (seconds after kClockOrigin).
export async function setClockAndDraw(page, t, frames = 3) {
  await page.evaluate(async ({at, frames}) => {
    const browser = X3D.getBrowser(document.getElementById('canvas'));
    for (let i = frames - 1; i >= 0; --i) {
      window.cadnurbsClock.set(at - i * 1e-3);
      if (window.cadnurbsClock.framesAllowed !== null) window.cadnurbsClock.framesAllowed = 1;
      await browser.nextFrame();
    }
  }, {at: kClockOrigin + t, frames});
}
