; The linear generator of COLIN (Coles, Coles, Fox and Long, "COLIN: Planning
; with Continuous Linear Numeric Change", JAIR 2012), in our style.
;
; - A generator runs for a fixed time (run-time ?g), burning fuel at a
;   constant rate (burn-rate ?g); its fuel must never fall below zero.
; - Its tank holds less than the run needs, so tanks must refuel it while it
;   runs: refuel requires (generator-running ?g) over all (required
;   concurrency) and adds fuel continuously at the tank's rate, never above
;   the generator's capacity. The net change during a refuel is
;   (refuel-rate ?t) - (burn-rate ?g), and several tanks may pour at once.
; - A tank can be used once.
(define (domain generator)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types generator tank - object)

  (:predicates
    (ready ?g - generator)              ; not started yet
    (generator-running ?g - generator)
    (generator-ran ?g - generator)
    (available ?t - tank))

  (:functions
    (fuel ?g - generator) - number
    (capacity ?g - generator) - number
    (burn-rate ?g - generator) - number
    (run-time ?g - generator) - number
    (refuel-rate ?t - tank) - number
    (refuel-time ?t - tank) - number)

  ;; the generator runs for its whole run time, burning fuel as it goes
  (:durative-action generate
    :parameters (?g - generator)
    :duration (= ?duration (run-time ?g))
    :condition (and (at start (ready ?g))
                    (over all (>= (fuel ?g) 0)))
    :effect (and (at start (not (ready ?g)))
                 (at start (generator-running ?g))
                 (at end (not (generator-running ?g)))
                 (at end (generator-ran ?g))
                 (decrease (fuel ?g) (* #t (burn-rate ?g)))))

  ;; a tank pours its fuel into a running generator
  (:durative-action refuel
    :parameters (?g - generator ?t - tank)
    :duration (= ?duration (refuel-time ?t))
    :condition (and (at start (available ?t))
                    (over all (generator-running ?g))
                    (over all (<= (fuel ?g) (capacity ?g))))
    :effect (and (at start (not (available ?t)))
                 (increase (fuel ?g) (* #t (refuel-rate ?t)))))
)
