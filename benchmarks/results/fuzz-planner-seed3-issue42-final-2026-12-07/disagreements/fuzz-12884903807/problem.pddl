(define (problem fuzz-12884903807-1) (:domain fuzz-12884903807)
  (:init (at 1 (f3)) (at 0.5 (f3)) (f0) (at 3 (not (f0))) (= (x0) 2) (at 1 (f3)) (at 1.0015 (not (f3))) (f4) (g0 o2))
  (:goal (and (f2) (>= (x0) 2) (preference pg (f2))))
  (:metric minimize (+ (total-time) (* 3 (is-violated pg)) (* 2 (is-violated pp)))))
